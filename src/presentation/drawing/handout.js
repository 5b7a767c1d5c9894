(function () {
  'use strict';
  var errors = window.handoutErrors || [];
  var $ = function (id) { return document.getElementById(id); };
  var all = function (root, sel) { return Array.prototype.slice.call(root.querySelectorAll(sel)); };
  var stepWord = document.body.getAttribute('data-word-step');
  var ofWord = document.body.getAttribute('data-word-of');
  var plans = all(document, 'figure.plan').map(function (fig) {
    return {
      fig: fig,
      n: +fig.getAttribute('data-steps'),
      pos: +fig.getAttribute('data-pos'),
      title: fig.getAttribute('data-title'),
      log: fig.querySelector('ol.log'),
      items: all(fig, '[data-step]').map(function (el) {
        var u = el.getAttribute('data-until');
        return { el: el, s: +el.getAttribute('data-step'), u: u === null ? Infinity : +u };
      })
    };
  });
  var sections = all(document, 'section.position');
  var tabs = all(document, 'button.tab');
  var frames = [];
  plans.forEach(function (p, j) { for (var k = 1; k <= p.n; k++) frames.push({ j: j, k: k }); });
  var g = -1, testing = /selftest/.test(location.hash);
  var where = $('where'), counter = $('counter'), sentence = $('sentence');
  var prevB = $('prev'), nextB = $('next'), firstB = $('first'), lastB = $('last');

  function setPlan(p, c, active) {
    p.items.forEach(function (it) {
      it.el.classList.toggle('off', !(it.s <= c && c < it.u));
      it.el.classList.toggle('now', active && it.s === c);
    });
    p.fig.classList.toggle('empty', c === 0);
    p.fig.classList.toggle('active', active);
  }
  function showPos(pos) {
    sections.forEach(function (s) { s.classList.toggle('current', +s.getAttribute('data-pos') === pos); });
    tabs.forEach(function (t) { t.classList.toggle('current', +t.getAttribute('data-pos') === pos); });
  }
  // First and last frame of a position.
  function span(pos) {
    var a = -1, b = -1;
    frames.forEach(function (f, i) { if (plans[f.j].pos === pos) { if (a < 0) a = i; b = i; } });
    return [a, b];
  }
  function show(i) {
    if (!frames.length) { if (sections.length) showPos(+sections[0].getAttribute('data-pos')); return; }
    i = Math.max(0, Math.min(frames.length - 1, i));
    g = i;
    var f = frames[i], P = plans[f.j];
    plans.forEach(function (p, j) { setPlan(p, j < f.j ? p.n : j === f.j ? f.k : 0, j === f.j); });
    showPos(P.pos);
    var li = P.log.querySelector('li[data-step="' + f.k + '"]');
    sentence.innerHTML = li ? li.innerHTML : '';
    where.textContent = P.title + ' — ' + stepWord + ' ' + f.k + ' ' + ofWord + ' ' + P.n;
    counter.textContent = (i + 1) + ' / ' + frames.length;
    var s = span(P.pos);
    prevB.disabled = i === 0;
    nextB.disabled = i === frames.length - 1;
    firstB.disabled = i === s[0];
    lastB.disabled = i === s[1];
    if (li) {
      // The current sentence at the bottom of the list, the ones before above it.
      var log = P.log, top = li.offsetTop, bottom = top + li.offsetHeight;
      if (top < log.scrollTop || bottom > log.scrollTop + log.clientHeight) {
        log.scrollTop = Math.max(0, Math.min(top, bottom - log.clientHeight));
      }
    }
    if (!testing) { try { history.replaceState(null, '', '#step=' + (i + 1)); } catch (e) { /* file: URLs may refuse */ } }
  }
  function fromHash() {
    var q = {};
    location.hash.replace(/^#/, '').split('&').forEach(function (kv) {
      var a = kv.split('='); if (a[0]) q[a[0]] = a.length > 1 ? decodeURIComponent(a[1]) : '';
    });
    if (q.pos) {
      var s = span(+q.pos);
      if (s[0] >= 0) return q.step === 'end' ? s[1] : Math.min(s[1], s[0] + Math.max(0, (+q.step || 1) - 1));
    }
    if (q.step === 'end') return frames.length - 1;
    if (q.step) return (+q.step || 1) - 1;
    return 0;
  }
  prevB.addEventListener('click', function () { show(g - 1); });
  nextB.addEventListener('click', function () { show(g + 1); });
  firstB.addEventListener('click', function () { if (frames.length) show(span(plans[frames[g].j].pos)[0]); });
  lastB.addEventListener('click', function () { if (frames.length) show(span(plans[frames[g].j].pos)[1]); });
  tabs.forEach(function (t) {
    t.addEventListener('click', function () { var s = span(+t.getAttribute('data-pos')); if (s[0] >= 0) show(s[0]); else showPos(+t.getAttribute('data-pos')); });
  });
  document.addEventListener('keydown', function (e) {
    if (e.altKey || e.ctrlKey || e.metaKey || !frames.length) return;
    var d = { ArrowRight: 1, PageDown: 1, ArrowLeft: -1, PageUp: -1 }[e.key];
    if (d) { e.preventDefault(); show(g + d); }
    else if (e.key === 'Home') { e.preventDefault(); firstB.click(); }
    else if (e.key === 'End') { e.preventDefault(); lastB.click(); }
  });
  window.addEventListener('hashchange', function () { if (!testing) show(fromHash()); });

  // Shown on the page: no ancestor with display none (checkVisibility()
  // cannot be used: Chromium reports a hidden SVG <g> as visible).
  function visible(el) {
    if (getComputedStyle(el).visibility === 'hidden') return false;
    for (var e = el; e && e.nodeType === 1; e = e.parentNode) {
      if (getComputedStyle(e).display === 'none') return false;
    }
    return true;
  }
  function key(e) { document.dispatchEvent(new KeyboardEvent('keydown', { key: e, bubbles: true })); }
  // Step through the whole handout with Next; check each step shows its
  // own elements (and no later ones) and its sentence; then Previous, keys, tabs.
  function selftest() {
    var fails = [], checked = 0, drawn = 0, before = null;
    var fail = function (m) { if (fails.length < 12) fails.push(m); };
    show(0);
    for (var i = 0; i < frames.length; i++) {
      if (i > 0) nextB.click();
      var f = frames[i], P = plans[f.j], at = P.fig.id + ' step ' + f.k;
      if (g !== i) { fail('Next did not reach ' + at); break; }
      var li = P.log.querySelector('li[data-step="' + f.k + '"]');
      var s = sentence.innerHTML;
      if (!li || !s || s !== li.innerHTML) fail('sentence of ' + at + ' not shown');
      if (s === before) fail('sentence unchanged at ' + at);
      before = s;
      if (!P.fig.classList.contains('active') || !visible(P.fig)) fail(at + ': plan not shown');
      var own = 0, svg = 0;
      P.items.forEach(function (it) {
        var want = it.s <= f.k && f.k < it.u;
        if (visible(it.el) !== want) fail(at + ': element of step ' + it.s + (want ? ' hidden' : ' shown'));
        if (it.s === f.k && want) {
          own++; checked++;
          if (it.el.closest('svg')) svg++;
          if (!it.el.classList.contains('now')) fail(at + ': own element not marked');
        }
      });
      if (!own) fail(at + ': revealed nothing');
      if (svg) drawn++;
    }
    if (frames.length > 1) {
      var last = frames.length - 1, L = frames[last], LP = plans[L.j];
      show(last); prevB.click();
      if (g !== last - 1) fail('Previous did not go back');
      if (frames[g].j === L.j) {
        LP.items.forEach(function (it) { if (it.s === L.k && visible(it.el)) fail('Previous left step ' + L.k + ' shown'); });
      }
      key('ArrowRight'); if (g !== last) fail('ArrowRight did not advance');
      key('ArrowLeft'); if (g !== last - 1) fail('ArrowLeft did not go back');
      key('Home'); if (g !== span(plans[frames[g].j].pos)[0]) fail('Home did not go to the start of the position');
      key('End'); if (g !== span(plans[frames[g].j].pos)[1]) fail('End did not show the whole position');
      if (tabs.length > 1) {
        tabs[1].click();
        var cur = all(document, 'section.position.current');
        if (cur.length !== 1 || cur[0].getAttribute('data-pos') !== tabs[1].getAttribute('data-pos')) fail('tab did not switch the position');
      }
    }
    var ok = !fails.length && !errors.length;
    var res = (ok ? 'SELFTEST PASS' : 'SELFTEST FAIL') + ' steps=' + frames.length + ' plans=' + plans.length +
      ' elements=' + checked + ' drawing-steps=' + drawn +
      (fails.length ? ' failures: ' + fails.join(' | ') : '') + (errors.length ? ' errors: ' + errors.join(' | ') : '');
    document.title = res;
    var pre = $('selftest'); pre.textContent = res; pre.hidden = false;
  }
  try {
    if (testing) selftest(); else show(fromHash());
  } catch (e) {
    errors.push(String(e && e.stack || e));
    if (testing) { document.title = 'SELFTEST FAIL errors: ' + errors.join(' | '); }
    throw e;
  }
})();
