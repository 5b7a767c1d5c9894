//! The house's rules, read from the code itself (docs/architecture.md):
//! one direction of dependency between the layers, no cycle between
//! files, no file over 700 lines and no function over 120, the library
//! neither printing nor touching files outside its front door (`study`).
//! Each rule is also shown to fail on a deliberately broken house.

use std::collections::{BTreeMap, BTreeSet};
use std::path::Path;

/// The layers, lowest first: a module may use only modules of lower
/// layers (base modules may use each other, without a cycle).
const LAYERS: &[&[&str]] = &[
    &[
        "accuracy", "error", "format", "geom", "json", "lang", "progress",
    ],
    &["model"],
    &["kinematics"],
    &["kinetostatics", "studies", "verification"],
    &["pipeline"],
    &["words"],
    &["grading"],
    &["presentation"],
    &["study"],
];

/// The binary's files and the crate root: they use the library's public
/// API only, which the compiler enforces.
const OUTSIDE: &[&str] = &[
    "lib.rs",
    "main.rs",
    "cli.rs",
    "serve.rs",
    "terminal.rs",
    "signals.rs",
];

fn layer(module: &str) -> Option<usize> {
    LAYERS.iter().position(|l| l.contains(&module))
}

/// Every source file of the library: its path under `src/` and its text.
fn sources() -> BTreeMap<String, String> {
    fn walk(dir: &Path, root: &Path, out: &mut BTreeMap<String, String>) {
        for e in std::fs::read_dir(dir).unwrap() {
            let p = e.unwrap().path();
            if p.is_dir() {
                walk(&p, root, out);
            } else if p.extension().is_some_and(|x| x == "rs") {
                let rel = p
                    .strip_prefix(root)
                    .unwrap()
                    .to_string_lossy()
                    .replace('\\', "/");
                if !OUTSIDE.contains(&rel.as_str()) {
                    out.insert(rel, std::fs::read_to_string(&p).unwrap());
                }
            }
        }
    }
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let mut out = BTreeMap::new();
    walk(&root, &root, &mut out);
    out
}

/// A file's module path: `kinematics/construction/mod.rs` is
/// `[kinematics, construction]`.
fn module_of(file: &str) -> Vec<String> {
    let mut parts: Vec<String> = file
        .trim_end_matches(".rs")
        .split('/')
        .map(String::from)
        .collect();
    if parts.last().is_some_and(|p| p == "mod") {
        parts.pop();
    }
    parts
}

/// The code without its unit tests (`#[cfg(test)] mod … { … }`), whose
/// `super` is their own file.
fn without_unit_tests(code: &str) -> String {
    let mut out = code.to_string();
    while let Some(k) = out.find("#[cfg(test)]") {
        let rest = &out[k..];
        let Some(open) = rest.find('{') else { break };
        let mut depth = 0;
        let mut end = rest.len();
        for (i, c) in rest[open..].char_indices() {
            match c {
                '{' => depth += 1,
                '}' => {
                    depth -= 1;
                    if depth == 0 {
                        end = open + i + 1;
                        break;
                    }
                }
                _ => {}
            }
        }
        out.replace_range(k..k + end, "");
    }
    out
}

/// The code without comments and string literals (a path in a doc
/// comment or a message is not an import).
fn code(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    let b = text.as_bytes();
    let mut i = 0;
    while i < b.len() {
        if b[i] == b'/' && b.get(i + 1) == Some(&b'/') {
            while i < b.len() && b[i] != b'\n' {
                i += 1;
            }
        } else if b[i] == b'"' {
            i += 1;
            while i < b.len() && b[i] != b'"' {
                i += if b[i] == b'\\' { 2 } else { 1 };
            }
            i += 1;
            out.push_str("\"\"");
        } else if b[i] == b'r' && b.get(i + 1) == Some(&b'#') && b.get(i + 2) == Some(&b'"') {
            // r#"…"#
            i += 3;
            while i + 1 < b.len() && !(b[i] == b'"' && b[i + 1] == b'#') {
                i += 1;
            }
            i += 2;
            out.push_str("\"\"");
        } else {
            out.push(b[i] as char);
            i += 1;
        }
    }
    out
}

/// Every module path the code names through `crate::`, `super::` or
/// `self::`, resolved from `me` (the file's module),
/// with the names inside braces of a `use` group each taken whole.
fn named_paths(code: &str, me: &[String]) -> Vec<Vec<String>> {
    let ident = |c: char| c.is_alphanumeric() || c == '_';
    let mut out = Vec::new();
    let chars: Vec<char> = code.chars().collect();
    let mut i = 0;
    while i < chars.len() {
        let at_word = i == 0 || !ident(chars[i - 1]) && chars[i - 1] != ':';
        let rest: String = chars[i..chars.len().min(i + 7)].iter().collect();
        let start = ["crate::", "super::", "self::"]
            .iter()
            .find(|s| at_word && rest.starts_with(**s));
        let Some(start) = start else {
            i += 1;
            continue;
        };
        // The path up to what is not an identifier or `::` (a brace
        // opens a group).
        let mut j = i;
        while j < chars.len() && (ident(chars[j]) || chars[j] == ':') {
            j += 1;
        }
        let path: String = chars[i..j].iter().collect();
        let mut segs: Vec<String> = path
            .split("::")
            .filter(|s| !s.is_empty())
            .map(String::from)
            .collect();
        // `super` of `a/b.rs` and of `a/b/mod.rs` alike is `a`.
        let mut base: Vec<String> = match *start {
            "crate::" => Vec::new(),
            "self::" => me.to_vec(),
            _ => me[..me.len().saturating_sub(1)].to_vec(),
        };
        segs.remove(0);
        while segs.first().is_some_and(|s| s == "super") {
            segs.remove(0);
            base.pop();
        }
        let mut prefix = base.clone();
        prefix.extend(segs);
        if j < chars.len() && chars[j] == '{' {
            // A use group: each name inside the braces (one level deep).
            let mut depth = 0;
            let mut k = j;
            let mut item = String::new();
            while k < chars.len() {
                let c = chars[k];
                match c {
                    '{' => {
                        depth += 1;
                        if depth > 1 {
                            item.push(c);
                        }
                    }
                    '}' => {
                        depth -= 1;
                        if depth == 0 {
                            break;
                        }
                        item.push(c);
                    }
                    ',' if depth == 1 => {
                        push_item(&prefix, &item, &mut out);
                        item.clear();
                    }
                    _ => item.push(c),
                }
                k += 1;
            }
            push_item(&prefix, &item, &mut out);
            i = k;
        } else {
            out.push(prefix);
            i = j;
        }
    }
    out
}

fn push_item(prefix: &[String], item: &str, out: &mut Vec<Vec<String>>) {
    let item = item.split(" as ").next().unwrap_or("").trim();
    let item = item.split('{').next().unwrap_or("");
    if item.is_empty() {
        // The empty item after a group's trailing comma.
        return;
    }
    let mut p = prefix.to_vec();
    p.extend(
        item.split("::")
            .map(str::trim)
            .filter(|s| !s.is_empty() && *s != "self")
            .map(String::from),
    );
    out.push(p);
}

/// The file a module path lands in: the longest prefix that is a file.
fn file_of(path: &[String], files: &BTreeMap<Vec<String>, String>) -> Option<String> {
    (1..=path.len())
        .rev()
        .find_map(|k| files.get(&path[..k]).cloned())
}

/// Where a path that lands in `file` really leads: a name that `file`
/// only re-exports (`pub use child::Name;`) is the child's.
fn through_reexports(
    path: &[String],
    file: String,
    sources: &BTreeMap<String, String>,
    files: &BTreeMap<Vec<String>, String>,
) -> String {
    let module = module_of(&file);
    let Some(name) = path.get(module.len()) else {
        return file;
    };
    let code = without_unit_tests(&code(&sources[&file]));
    for stmt in code.split(';') {
        let s = stmt.trim();
        let Some(rest) = s
            .strip_prefix("pub use ")
            .or_else(|| s.strip_prefix("pub(crate) use "))
            .or_else(|| s.strip_prefix("pub(super) use "))
        else {
            continue;
        };
        // `pub use child::*`: the names the child defines.
        if let Some(child) = rest.strip_suffix("::*") {
            let mut m = module.clone();
            m.push(child.trim().to_string());
            if let Some(f) = files.get(&m)
                && defines(&sources[f], name)
            {
                return f.clone();
            }
            continue;
        }
        // `child::Name`, `child::{A, Name}`, `child::Name as Other`.
        let names_it = rest
            .split([',', '{', '}', ':'])
            .map(|w| w.split(" as ").last().unwrap_or("").trim())
            .any(|w| w == name);
        if !names_it {
            continue;
        }
        let first = rest.split("::").next().unwrap_or("").trim();
        let target: Vec<String> = match first {
            "crate" => rest
                .split("::")
                .skip(1)
                .map(|s| s.trim().to_string())
                .collect(),
            "super" => {
                let mut b = module[..module.len().saturating_sub(1)].to_vec();
                b.extend(rest.split("::").skip(1).map(|s| s.trim().to_string()));
                b
            }
            child => {
                let mut b = module.clone();
                b.push(child.to_string());
                b
            }
        };
        let target: Vec<String> = target
            .into_iter()
            .take_while(|s| !s.contains('{') && !s.contains(' '))
            .collect();
        if let Some(f) = file_of(&target, files)
            && f != file
        {
            return f;
        }
    }
    file
}

/// Whether `text` defines an item called `name`.
fn defines(text: &str, name: &str) -> bool {
    let code = code(text);
    [
        "struct ", "enum ", "fn ", "const ", "static ", "type ", "trait ", "mod ",
    ]
    .iter()
    .any(|k| {
        code.match_indices(&format!("{k}{name}")).any(|(i, m)| {
            let after = code[i + m.len()..].chars().next();
            !after.is_some_and(|c| c.is_alphanumeric() || c == '_')
        })
    })
}

/// What is wrong with a house of `sources`: upward imports and cycles
/// between files.
fn violations(sources: &BTreeMap<String, String>) -> Vec<String> {
    let files: BTreeMap<Vec<String>, String> =
        sources.keys().map(|f| (module_of(f), f.clone())).collect();
    let mut problems = Vec::new();
    let mut edges: BTreeMap<String, BTreeSet<String>> = BTreeMap::new();
    for (file, text) in sources {
        let me = module_of(file);
        let dir = file.ends_with("mod.rs");
        let top = me[0].clone();
        let Some(mine) = layer(&top) else {
            problems.push(format!("{file}: module `{top}` is in no layer"));
            continue;
        };
        let code = without_unit_tests(&code(text));
        let mut used: BTreeSet<String> = BTreeSet::new();
        for p in named_paths(&code, &me) {
            // The crate root's re-exports are the API's, not a way round
            // the layers: inside, a path names its module.
            if let Some(first) = p.first()
                && first.starts_with(|c: char| c.is_uppercase())
            {
                problems.push(format!(
                    "{file}: uses crate::{} through the crate root",
                    p.join("::")
                ));
            }
            if let Some(first) = p.first()
                && let Some(theirs) = layer(first)
                && first != &top
                && (theirs > mine || (theirs == mine && mine > 0))
            {
                problems.push(format!(
                    "{file}: uses crate::{} (layer {theirs}) from layer {mine}",
                    p.join("::")
                ));
            }
            if let Some(f) = file_of(&p, &files).map(|f| through_reexports(&p, f, sources, &files))
                && &f != file
            {
                used.insert(f);
            }
        }
        // A directory module's children named bare (`child::item`).
        if dir {
            for (m, f) in &files {
                if m.len() == me.len() + 1 && m[..me.len()] == me[..] {
                    let name = &m[me.len()];
                    let pat = format!("{name}::");
                    let bare = code.match_indices(&pat).any(|(k, _)| {
                        let before = code[..k].chars().next_back();
                        !before.is_some_and(|c| c.is_alphanumeric() || c == '_' || c == ':')
                    });
                    if bare {
                        used.insert(f.clone());
                    }
                }
            }
        }
        edges.insert(file.clone(), used);
    }
    for cycle in cycles(&edges) {
        problems.push(format!("a cycle of files: {}", cycle.join(" → ")));
    }
    problems
}

/// The strongly connected components of more than one file (Tarjan).
fn cycles(edges: &BTreeMap<String, BTreeSet<String>>) -> Vec<Vec<String>> {
    struct T<'a> {
        edges: &'a BTreeMap<String, BTreeSet<String>>,
        index: BTreeMap<&'a str, usize>,
        low: BTreeMap<&'a str, usize>,
        stack: Vec<&'a str>,
        on: BTreeSet<&'a str>,
        out: Vec<Vec<String>>,
    }
    fn visit<'a>(t: &mut T<'a>, v: &'a str) {
        let n = t.index.len();
        t.index.insert(v, n);
        t.low.insert(v, n);
        t.stack.push(v);
        t.on.insert(v);
        if let Some(ws) = t.edges.get(v) {
            for w in ws {
                let w = w.as_str();
                if !t.index.contains_key(w) {
                    visit(t, w);
                    let lw = t.low[w];
                    let lv = t.low[v];
                    t.low.insert(v, lv.min(lw));
                } else if t.on.contains(w) {
                    let iw = t.index[w];
                    let lv = t.low[v];
                    t.low.insert(v, lv.min(iw));
                }
            }
        }
        if t.low[v] == t.index[v] {
            let mut comp = Vec::new();
            while let Some(w) = t.stack.pop() {
                t.on.remove(w);
                comp.push(w.to_string());
                if w == v {
                    break;
                }
            }
            if comp.len() > 1 {
                comp.sort();
                t.out.push(comp);
            }
        }
    }
    let mut t = T {
        edges,
        index: BTreeMap::new(),
        low: BTreeMap::new(),
        stack: Vec::new(),
        on: BTreeSet::new(),
        out: Vec::new(),
    };
    for v in edges.keys() {
        if !t.index.contains_key(v.as_str()) {
            visit(&mut t, v);
        }
    }
    t.out
}

#[test]
fn one_direction_and_no_cycle() {
    let v = violations(&sources());
    assert!(v.is_empty(), "{} problems:\n{}", v.len(), v.join("\n"));
}

#[test]
fn an_upward_import_and_a_cycle_are_caught() {
    let mut house = sources();
    // The kinematics kernel asking the presentation for something.
    let key = house
        .keys()
        .find(|k| k.starts_with("kinematics/positions"))
        .cloned()
        .expect("the positions' file");
    house
        .get_mut(&key)
        .unwrap()
        .push_str("\nuse crate::presentation::report::to_json;\n");
    let v = violations(&house);
    assert!(
        v.iter()
            .any(|p| p.contains(&key) && p.contains("crate::presentation::report")),
        "{v:?}"
    );
    // A path through the crate root's re-exports.
    let mut house = sources();
    house
        .get_mut("geom.rs")
        .unwrap()
        .push_str("\nfn refuse() -> crate::Error { unreachable!() }\n");
    let v = violations(&house);
    assert!(
        v.iter()
            .any(|p| p.contains("geom.rs") && p.contains("through the crate root")),
        "{v:?}"
    );
    // Two files of one layer naming each other.
    let mut house = sources();
    house
        .get_mut("geom.rs")
        .unwrap()
        .push_str("\nuse crate::format::num;\n");
    house
        .get_mut("format.rs")
        .unwrap()
        .push_str("\nuse crate::geom::Pose;\n");
    let v = violations(&house);
    assert!(
        v.iter()
            .any(|p| p.contains("cycle") && p.contains("geom.rs") && p.contains("format.rs")),
        "{v:?}"
    );
}

/// Lines of a file and of its functions (from `fn` to its closing brace).
fn longest_functions(text: &str) -> Vec<(usize, usize, String)> {
    let lines: Vec<&str> = text.lines().collect();
    let mut out = Vec::new();
    for (i, line) in lines.iter().enumerate() {
        let t = line.trim_start();
        let t = t
            .strip_prefix("pub ")
            .or_else(|| t.strip_prefix("pub(crate) "))
            .or_else(|| t.strip_prefix("pub(super) "))
            .unwrap_or(t);
        let t = t.strip_prefix("const ").unwrap_or(t);
        let Some(rest) = t.strip_prefix("fn ") else {
            continue;
        };
        let name: String = rest
            .chars()
            .take_while(|c| c.is_alphanumeric() || *c == '_')
            .collect();
        let (mut depth, mut opened) = (0i64, false);
        for (j, l) in lines.iter().enumerate().skip(i) {
            let c = code(l);
            for ch in c.chars() {
                match ch {
                    '{' => {
                        depth += 1;
                        opened = true;
                    }
                    '}' => depth -= 1,
                    _ => {}
                }
            }
            if !opened && c.trim_end().ends_with(';') {
                break;
            }
            if opened && depth == 0 {
                out.push((j - i + 1, i + 1, name.clone()));
                break;
            }
        }
    }
    out
}

#[test]
fn no_file_over_700_lines_and_no_function_over_120() {
    let mut long = Vec::new();
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let mut all = sources();
    for f in OUTSIDE.iter().filter(|f| **f != "lib.rs") {
        all.insert(
            f.to_string(),
            std::fs::read_to_string(root.join(f)).unwrap(),
        );
    }
    for (file, text) in &all {
        let n = text.lines().count();
        if n > 700 {
            long.push(format!("{file}: {n} lines"));
        }
        for (len, at, name) in longest_functions(text) {
            if len > 120 {
                long.push(format!("{file}:{at}: fn {name} has {len} lines"));
            }
        }
    }
    assert!(long.is_empty(), "{}", long.join("\n"));
    // The measure itself measures.
    let body = "fn f() {\n".to_string() + &"    let x = 1;\n".repeat(130) + "}\n";
    assert_eq!(longest_functions(&body)[0].0, 132);
}

#[test]
fn the_library_prints_nothing_and_only_its_front_door_touches_files() {
    let mut found = Vec::new();
    for (file, text) in &sources() {
        let c = code(text);
        for bad in ["println!", "print!", "stdout()", "stderr()", "dbg!"] {
            if has_word(&c, bad) {
                found.push(format!("{file}: {bad}"));
            }
        }
        if !file.starts_with("study/") {
            for bad in ["std::fs", "fs::", "File::", "OpenOptions"] {
                if has_word(&c, bad) {
                    found.push(format!("{file}: {bad} outside the front door"));
                }
            }
        }
    }
    assert!(found.is_empty(), "{}", found.join("\n"));
}

/// Whether `pat` stands in `code` not as the tail of a longer name
/// (`eprintln!` has `println!` in it too: both are printing).
fn has_word(code: &str, pat: &str) -> bool {
    code.match_indices(pat).any(|(k, _)| {
        let before = code[..k].chars().next_back();
        !before.is_some_and(|c| c.is_alphanumeric() && c != 'e' || c == '_')
            || before == Some('e') && (pat.starts_with("print"))
    })
}

/// Every phrase is in the words' catalogues: outside `lang.rs` no code
/// (unit tests aside) names a language other than the default English,
/// so that a new language is its catalogue file and its line in
/// `lang.rs`.
#[test]
fn phrases_live_in_the_words_catalogues() {
    let mut found = Vec::new();
    for (file, text) in &sources() {
        if file == "lang.rs" {
            continue;
        }
        let c = without_unit_tests(&code(text));
        for l in ["Lang::Uk", "Lang::Ru"] {
            if c.contains(l) {
                found.push(format!("{file}: {l}"));
            }
        }
    }
    assert!(found.is_empty(), "{}", found.join("\n"));
}

/// The string literals of `text` ("…", r"…", r#"…"#), as written.
fn string_literals(text: &str) -> Vec<String> {
    let mut out = Vec::new();
    let b = text.as_bytes();
    let mut i = 0;
    while i < b.len() {
        if b[i] == b'/' && b.get(i + 1) == Some(&b'/') {
            while i < b.len() && b[i] != b'\n' {
                i += 1;
            }
        } else if b[i] == b'\'' && b.get(i + 1) == Some(&b'"') && b.get(i + 2) == Some(&b'\'') {
            i += 3;
        } else if b[i] == b'"' {
            let start = i + 1;
            i += 1;
            while i < b.len() && b[i] != b'"' {
                i += if b[i] == b'\\' { 2 } else { 1 };
            }
            out.push(String::from_utf8_lossy(&b[start..i.min(b.len())]).into_owned());
            i += 1;
        } else if b[i] == b'r' && b.get(i + 1) == Some(&b'#') && b.get(i + 2) == Some(&b'"') {
            let start = i + 3;
            i += 3;
            while i + 1 < b.len() && !(b[i] == b'"' && b[i + 1] == b'#') {
                i += 1;
            }
            out.push(String::from_utf8_lossy(&b[start..i.min(b.len())]).into_owned());
            i += 2;
        } else {
            i += 1;
        }
    }
    out
}

/// Words of a language in string literals outside `words/` and `lang.rs`
/// (unit tests aside): a literal with a Cyrillic letter, but the letters
/// a standard fixes whatever the language (ГОСТ 2.104's letter "У" of a
/// study project).
fn language_in_literals(sources: &BTreeMap<String, String>) -> Vec<String> {
    const STANDARD_LETTERS: &[(&str, &str)] = &[("model/scene/sheet.rs", "\\\"У\\\"")];
    let mut found = Vec::new();
    for (file, text) in sources {
        if file.starts_with("words/") || file == "lang.rs" {
            continue;
        }
        for lit in string_literals(&without_unit_tests(text)) {
            let mut rest = lit.clone();
            for (f, allowed) in STANDARD_LETTERS {
                if f == file {
                    rest = rest.replace(allowed, "");
                }
            }
            if rest.chars().any(|c| ('\u{0400}'..='\u{04FF}').contains(&c)) {
                found.push(format!("{file}: \"{lit}\""));
            }
        }
    }
    found
}

/// A new language is its catalogue file and its line in `lang.rs`: no
/// other code holds a language's words, in its names or its strings (the
/// titles `check` reads, the balancing moment's subscript).
#[test]
fn no_language_words_outside_the_catalogues() {
    let found = language_in_literals(&sources());
    assert!(found.is_empty(), "{}", found.join("\n"));
}

#[test]
fn language_words_in_literals_are_caught() {
    let mut house = sources();
    house.get_mut("grading/drawing.rs").unwrap().push_str(
        "\nfn f(t: &str) -> bool { t.contains(\"швидкост\") || t.contains(r#\"план\"#) }\n",
    );
    let v = language_in_literals(&house);
    assert!(v.iter().any(|p| p.contains("швидкост")), "{v:?}");
    assert!(v.iter().any(|p| p.contains("план")), "{v:?}");
    // A unit test's strings are not the product's.
    let mut house = sources();
    house
        .get_mut("grading/drawing.rs")
        .unwrap()
        .push_str("\n#[cfg(test)]\nmod t { fn g() -> &'static str { \"План прискорень\" } }\n");
    assert!(language_in_literals(&house).is_empty());
}

/// Every source file under `src/`, the binary's and the crate root's too.
fn every_source() -> BTreeMap<String, String> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let mut all = sources();
    for f in OUTSIDE {
        all.insert(
            f.to_string(),
            std::fs::read_to_string(root.join(f)).unwrap(),
        );
    }
    all
}

/// Whether an attribute's text allows (or expects) `dead_code`, or the
/// whole `unused` group it belongs to.
fn silences_dead_code(attr: &str) -> bool {
    let a: String = attr.chars().filter(|c| !c.is_whitespace()).collect();
    ["allow(", "expect("].iter().any(|k| {
        a.match_indices(k).any(|(p, _)| {
            let args = &a[p + k.len()..];
            let args = &args[..args.find(')').unwrap_or(args.len())];
            args.split(',').any(|x| x == "dead_code" || x == "unused")
        })
    })
}

/// Where the dead-code lint is silenced in `sources`: an inner attribute
/// (`#![…]`: a module or the whole crate) always, an item's own
/// `#[allow(dead_code)]` where the line right above it is no `//`
/// comment saying why.
fn silenced_dead_code(sources: &BTreeMap<String, String>) -> Vec<String> {
    let mut found = Vec::new();
    for (file, text) in sources {
        let lines: Vec<&str> = text.lines().collect();
        let mut i = 0;
        while i < lines.len() {
            let t = lines[i].trim_start();
            if !(t.starts_with("#[") || t.starts_with("#![")) {
                i += 1;
                continue;
            }
            // The whole attribute, over as many lines as its brackets take.
            let start = i;
            let mut attr = String::new();
            let mut depth = 0i64;
            loop {
                let l = lines[i];
                attr.push_str(l);
                attr.push('\n');
                depth += l.matches('[').count() as i64 - l.matches(']').count() as i64;
                i += 1;
                if depth <= 0 || i == lines.len() {
                    break;
                }
            }
            if !silences_dead_code(&attr) {
                continue;
            }
            let at = format!("{file}:{}", start + 1);
            if t.starts_with("#![") {
                found.push(format!("{at}: dead code allowed module- or crate-wide"));
                continue;
            }
            let above = start.checked_sub(1).map(|k| lines[k].trim_start());
            let why = above.is_some_and(|a| {
                a.starts_with("//") && !a.starts_with("///") && !a.starts_with("//!") && a.len() > 3
            });
            if !why {
                found.push(format!(
                    "{at}: allow(dead_code) without a comment line right above it saying why"
                ));
            }
        }
    }
    found
}

/// The compiler sees all the code: no module- or crate-wide
/// `allow(dead_code)` (code only the tests use is compiled only with the
/// `internals` feature instead), and an item's own only under a comment
/// saying why.
#[test]
fn dead_code_is_allowed_only_item_by_item_and_said_why() {
    let found = silenced_dead_code(&every_source());
    assert!(found.is_empty(), "{}", found.join("\n"));
    // The check itself catches each kind.
    let mut house = BTreeMap::new();
    house.insert(
        "crate.rs".to_string(),
        "//! A crate.\n#![cfg_attr(\n    not(feature = \"internals\"),\n    allow(dead_code, unused_imports)\n)]\n".to_string(),
    );
    house.insert("module.rs".to_string(), "#![allow(unused)]\n".to_string());
    house.insert(
        "item.rs".to_string(),
        "/// A thing.\n#[allow(dead_code)]\nfn f() {}\n".to_string(),
    );
    house.insert(
        "said.rs".to_string(),
        "/// A thing.\n// Read only by a unit test.\n#[allow(clippy::x, dead_code)]\nfn f() {}\n"
            .to_string(),
    );
    let v = silenced_dead_code(&house);
    assert_eq!(v.len(), 3, "{v:?}");
    assert!(v[0].starts_with("crate.rs:2: dead code allowed"), "{v:?}");
    assert!(
        v[1].starts_with("item.rs:2: allow(dead_code) without"),
        "{v:?}"
    );
    assert!(v[2].starts_with("module.rs:1: dead code allowed"), "{v:?}");
}

/// The names `src/lib.rs` re-exports at the root for the API (its `pub
/// use` lines not behind `internals`, and its public modules).
fn root_api(lib: &str) -> Vec<String> {
    let mut out = Vec::new();
    let mut internal = false;
    let mut stmt = String::new();
    for line in lib.lines() {
        let t = line.trim();
        if t.starts_with("#[cfg(feature = \"internals\")]") {
            internal = true;
            continue;
        }
        if t.starts_with("#[") || t.starts_with("//") {
            continue;
        }
        if stmt.is_empty() && !(t.starts_with("pub use ") || t.starts_with("pub mod ")) {
            internal = false;
            continue;
        }
        stmt.push_str(t);
        stmt.push(' ');
        if !t.ends_with(';') {
            continue;
        }
        let s = std::mem::take(&mut stmt);
        if std::mem::take(&mut internal) {
            continue;
        }
        if let Some(m) = s.strip_prefix("pub mod ") {
            out.push(m.trim().trim_end_matches(';').to_string());
            continue;
        }
        let body = s
            .trim_start_matches("pub use ")
            .trim()
            .trim_end_matches(';');
        let names = match body.find('{') {
            Some(i) => body[i + 1..body.rfind('}').unwrap_or(body.len())].to_string(),
            None => body.to_string(),
        };
        for n in names.split(',') {
            let n = n.trim();
            if n.is_empty() || n == "self" {
                continue;
            }
            let last = n.rsplit("::").next().unwrap_or(n);
            let last = last.rsplit(" as ").next().unwrap_or(last);
            out.push(last.trim().to_string());
        }
    }
    out
}

/// docs/architecture.md's list of the API, as rustdoc lists it, names
/// every item the root re-exports and every public module.
#[test]
fn the_api_list_in_the_docs_names_every_root_item() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let lib = std::fs::read_to_string(root.join("src/lib.rs")).unwrap();
    let doc = std::fs::read_to_string(root.join("docs/architecture.md")).unwrap();
    let from = doc
        .find("## The API, item by item")
        .expect("docs/architecture.md: no section \"The API, item by item\"");
    let list = &doc[from..];
    let list = &list[..list[3..].find("\n## ").map_or(list.len(), |i| i + 3)];
    let names = root_api(&lib);
    assert!(names.len() > 30, "{names:?}");
    let missing: Vec<&String> = names
        .iter()
        .filter(|n| {
            let module = format!("`{n}::");
            // rustdoc lists an item by the module that defines it.
            let defined = format!("::{n}`");
            !list.contains(&format!("`{n}`")) && !list.contains(&module) && !list.contains(&defined)
        })
        .collect();
    assert!(
        missing.is_empty(),
        "root items not in docs/architecture.md's API list: {missing:?}"
    );
}

/// What presentation may name from `kinematics::positions`: a solved
/// position's configuration, read, and the inputs described in words.
/// Every other item there solves (the position solver, the groups'
/// closed forms, the branches, the continuation).
const POSITIONS_READ: &[&str] = &["Configuration", "describe_input", "describe_input_with"];

/// Calls that solve: the position solver's methods, the output's extreme
/// positions found by root finding (the working stroke), the pipeline's
/// runs, the kinematic diagrams' sweep of positions, the studies that
/// solve what the sheets draw beyond the positions.
const SOLVING_CALLS: &[&str] = &[
    ".solve(",
    ".solve_at(",
    ".solve_coords(",
    ".solve_at_coords(",
    "working_stroke(",
    "working_stroke_start(",
    "stroke_start(",
    "in_line_extremes(",
    ".run(",
    ".run_each",
    ".run_rescaled(",
    "Diagrams::build(",
    "Diagrams::build_point(",
    "Chosen::of(",
    "SheetData::solve(",
    "trajectories(",
];

/// Where presentation solves (docs/architecture.md: it reads a finished
/// solution and never solves again): the position solver named, an item
/// of `kinematics::positions` that solves, a solving call
/// ([`SOLVING_CALLS`]).
fn presentation_solving(sources: &BTreeMap<String, String>) -> Vec<String> {
    let mut found = Vec::new();
    for (file, text) in sources
        .iter()
        .filter(|(f, _)| f.starts_with("presentation/"))
    {
        let c = without_unit_tests(&code(text));
        if has_word(&c, "PositionSolver") {
            found.push(format!("{file}: uses PositionSolver"));
        }
        for p in named_paths(&c, &module_of(file)) {
            if p.len() >= 2 && p[0] == "kinematics" && p[1] == "positions" {
                let item = p.get(2).map_or("", String::as_str);
                if !POSITIONS_READ.contains(&item) {
                    found.push(format!(
                        "{file}: uses crate::{} (solving: presentation reads {POSITIONS_READ:?} only)",
                        p.join("::")
                    ));
                }
            }
        }
        for call in SOLVING_CALLS {
            if !c.contains(call) {
                continue;
            }
            found.push(format!("{file}: solves ({call}…)"));
        }
    }
    found
}

/// Presentation never solves: the positions' trajectories and the
/// output's extreme positions are data of the solution
/// (`studies::trajectories`, computed by the study layer), not solved
/// where they are drawn.
#[test]
fn presentation_never_solves() {
    let found = presentation_solving(&sources());
    assert!(found.is_empty(), "{}", found.join("\n"));
}

#[test]
fn solving_in_presentation_is_caught() {
    let file = "presentation/drawing/positions.rs";
    // The position solver, imported and called.
    let mut house = sources();
    house.get_mut(file).unwrap().push_str(
        "\nuse crate::kinematics::positions::{Configuration, PositionSolver};\nfn f(an: &Analysis) { let mut ps = PositionSolver::new(&an.mech, &an.structure, an.need.clone()).unwrap(); let _ = ps.solve(0.0); }\n",
    );
    let v = presentation_solving(&house);
    for bad in [
        "uses PositionSolver",
        "crate::kinematics::positions::PositionSolver",
        "(.solve(…)",
    ] {
        assert!(
            v.iter().any(|p| p.contains(file) && p.contains(bad)),
            "{bad}: {v:?}"
        );
    }
    assert!(!v.iter().any(|p| p.contains("::Configuration")), "{v:?}");
    // A solving item of kinematics::positions under another name, and
    // the module whole.
    let mut house = sources();
    house
        .get_mut(file)
        .unwrap()
        .push_str("\nuse crate::kinematics::positions::solve_group_dyad as dyad;\nuse crate::kinematics::positions;\n");
    let v = presentation_solving(&house);
    assert!(
        v.iter().any(|p| p.contains("positions::solve_group_dyad")),
        "{v:?}"
    );
    assert!(
        v.iter()
            .any(|p| p.contains("uses crate::kinematics::positions (")),
        "{v:?}"
    );
    // The extreme positions' root finding, where it is not known.
    let mut house = sources();
    house
        .get_mut(file)
        .unwrap()
        .push_str("\nfn g(an: &Analysis) { let _ = an.working_stroke(0); }\n");
    let v = presentation_solving(&house);
    assert!(
        v.iter()
            .any(|p| p.contains(file) && p.contains("working_stroke(")),
        "{v:?}"
    );
}
