//! The reference's numbers: reals of [`BITS`] bits (`dashu-float`,
//! correctly rounded `sqrt`, `sin`, `cos`, `atan2`, π) and planar vectors
//! of them, with route (b)'s [`Number`] over them.

use crate::kinematics::analytic::equations::{Number, Vector};
use dashu_float::FBig;
use dashu_float::round::mode::HalfEven;
use kurbo::Vec2;
use std::ops::{Add, Div, Mul, Neg, Sub};

/// Working precision, bits (≈ 57 decimal digits).
pub const BITS: usize = 192;

/// The number type, public to the project's tests (`internals`) only:
/// the product reaches it through no public item.
macro_rules! real {
    ($vis:vis) => {
        /// A real number of [`BITS`] bits.
        #[derive(Clone, Debug, PartialEq, PartialOrd)]
        $vis struct Real(FBig<HalfEven, 2>);
    };
}
#[cfg(feature = "internals")]
real!(pub);
#[cfg(not(feature = "internals"))]
real!(pub(crate));

impl Real {
    /// The exact value of an f64 (every finite f64 is a dyadic rational).
    pub fn from_f64(x: f64) -> Real {
        let v = FBig::<HalfEven, 2>::try_from(x).expect("a finite number");
        Real(v.with_precision(BITS).value())
    }
    pub fn zero() -> Real {
        Real::from_f64(0.0)
    }
    pub fn one() -> Real {
        Real::from_f64(1.0)
    }
    /// π to [`BITS`] bits.
    pub fn pi() -> Real {
        static PI: std::sync::OnceLock<Real> = std::sync::OnceLock::new();
        PI.get_or_init(|| Real(FBig::<HalfEven, 2>::pi(BITS)))
            .clone()
    }
    #[cfg(feature = "internals")]
    /// Degrees to radians with the extended π.
    pub fn from_degrees(deg: &Real) -> Real {
        deg * &Real::pi() / Real::from_f64(180.0)
    }
    /// A decimal numeral ("-12.5", "3.25e-3") to [`BITS`] bits.
    pub fn from_decimal(s: &str) -> Option<Real> {
        let s = s.trim();
        let (mant, exp) = match s.find(['e', 'E']) {
            Some(i) => (&s[..i], s[i + 1..].parse::<i32>().ok()?),
            None => (s, 0),
        };
        let (neg, mant) = match mant.strip_prefix('-') {
            Some(r) => (true, r),
            None => (false, mant.strip_prefix('+').unwrap_or(mant)),
        };
        let mut v = Real::zero();
        let mut frac = 0i32;
        let mut seen_dot = false;
        let ten = Real::from_f64(10.0);
        let mut any = false;
        for c in mant.chars() {
            match c {
                '.' if !seen_dot => seen_dot = true,
                '0'..='9' => {
                    any = true;
                    v = v * &ten + Real::from_f64(f64::from(c as u8 - b'0'));
                    if seen_dot {
                        frac += 1;
                    }
                }
                _ => return None,
            }
        }
        if !any {
            return None;
        }
        let k = exp - frac;
        let mut p = Real::one();
        for _ in 0..k.unsigned_abs() {
            p = p * &ten;
        }
        let v = if k >= 0 { v * p } else { v / p };
        Some(if neg { -v } else { v })
    }
    /// The nearest f64.
    pub fn to_f64(&self) -> f64 {
        self.0.to_f64().value()
    }
    pub fn sqrt(&self) -> Real {
        Real(self.0.sqrt())
    }
    pub fn sin_cos(&self) -> (Real, Real) {
        let (s, c) = self.0.sin_cos();
        (Real(s), Real(c))
    }
    /// atan2(self, x).
    pub fn atan2(&self, x: &Real) -> Real {
        Real(self.0.atan2(&x.0))
    }
    pub fn abs(&self) -> Real {
        if self.is_negative() {
            -self
        } else {
            self.clone()
        }
    }
    pub fn is_negative(&self) -> bool {
        self.0 < FBig::<HalfEven, 2>::ZERO
    }
    pub fn max(self, o: Real) -> Real {
        if o > self { o } else { self }
    }
    pub fn square(&self) -> Real {
        self * self
    }
    /// The angle reduced to (−π, π] (approximately at the ends).
    fn wrap(&self) -> Real {
        let tau = Real::pi() * Real::from_f64(2.0);
        let k = (self / &tau).0.round();
        self - &(Real(k) * tau)
    }
}

macro_rules! binop {
    ($tr:ident, $f:ident) => {
        impl $tr<&Real> for &Real {
            type Output = Real;
            fn $f(self, o: &Real) -> Real {
                Real((&self.0).$f(&o.0))
            }
        }
        impl $tr<Real> for Real {
            type Output = Real;
            fn $f(self, o: Real) -> Real {
                Real(self.0.$f(o.0))
            }
        }
        impl $tr<&Real> for Real {
            type Output = Real;
            fn $f(self, o: &Real) -> Real {
                Real(self.0.$f(&o.0))
            }
        }
        impl $tr<Real> for &Real {
            type Output = Real;
            fn $f(self, o: Real) -> Real {
                Real((&self.0).$f(o.0))
            }
        }
    };
}
binop!(Add, add);
binop!(Sub, sub);
binop!(Mul, mul);
binop!(Div, div);

impl Neg for Real {
    type Output = Real;
    fn neg(self) -> Real {
        Real(-self.0)
    }
}

impl Neg for &Real {
    type Output = Real;
    fn neg(self) -> Real {
        Real(-self.0.clone())
    }
}

impl Number for Real {
    fn from_f64(x: f64) -> Real {
        Real::from_f64(x)
    }
    fn sqrt(&self) -> Real {
        Real::sqrt(self)
    }
    fn sin_cos(&self) -> (Real, Real) {
        Real::sin_cos(self)
    }
    fn atan2(&self, x: &Real) -> Real {
        Real::atan2(self, x)
    }
    fn wrap_angle(&self) -> Real {
        self.wrap()
    }
}

/// A planar vector of [`Real`]s.
pub type V2 = Vector<Real>;

impl Vector<Real> {
#[cfg(feature = "internals")]
    pub fn to_vec2(&self) -> Vec2 {
        Vec2::new(self.x.to_f64(), self.y.to_f64())
    }
#[cfg(feature = "internals")]
    pub fn to_point(&self) -> kurbo::Point {
        kurbo::Point::new(self.x.to_f64(), self.y.to_f64())
    }
    /// |a − b| as an f64, for an f64 `b`.
    pub fn dist_f64(&self, b: Vec2) -> f64 {
        self.sub(&V2::new(Real::from_f64(b.x), Real::from_f64(b.y)))
            .norm()
            .to_f64()
    }
}
