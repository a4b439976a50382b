// `make lint-comments`: comments and docs explain the code as it is. This check fails when a
// comment in src/, www/ (not the generated www/pkg/ and www/book/), the Makefile or
// Cargo.toml reports a measurement delta or a history ("3 % faster", "374 bytes off",
// "tried first", "before the change", "Over 500 lines"), and prints file:line, the rule and
// the line. Only the comments are read (Rust's `//`, `///`, `//!` and `/* */`, JavaScript's
// and CSS's, HTML's `<!-- -->`, the `#` of the Makefile and TOML), so that code and strings
// do not trip it. Measurements and their history belong in commit messages and the book.
//
// Usage: node .ci/comments.mjs [ROOT]   (ROOT: the repository, by default this file's parent)

import { readdirSync, readFileSync, statSync } from 'node:fs';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';

const ROOT = process.argv[2] ?? join(dirname(fileURLToPath(import.meta.url)), '..');

/** Where comments are read: folders walked, files read as they are. */
const DIRS = ['src', 'www'];
const FILES = ['Makefile', 'Cargo.toml'];
/** Generated or linked folders, not the project's own words. */
const SKIP = new Set(['www/pkg', 'www/book', 'node_modules']);
const EXTENSIONS = ['.rs', '.js', '.mjs', '.ts', '.css', '.html', '.toml'];

/** [rule, pattern]: each pattern is matched against the comment text of one line. */
const RULES = [
  ['a speed change in per cent', /\d\s*%\s*(faster|slower|quicker)\b/i],
  ['a cost change in per cent', /\d\s*%\s*(more|fewer|less)\s+(instructions|time|cycles|work|bytes|memory)\b/i],
  ['a speed change', /\b(faster|slower) than (before|it was)\b/i],
  ['a change in times', /\d\s*(x|×|times) (faster|slower|smaller|larger)\b/i],
  ['a figure and the one before it', /\bfrom [\d.,]+\s*(ms|s|bytes|KB|%) to [\d.,]+\s*(ms|s|bytes|KB|%)/i],
  ['a former value', /\((was|formerly) [\d.,]/i],
  ['a size change', /\b(bytes|KB|kB|KiB|MB)\s+(smaller|larger|bigger|off|saved|shorter)\b/i],
  ['a size saved', /\banother\s+[\d,.]+\s*(bytes|KB|kB|KiB)\b/i],
  ['a size that something needed', /\d[\d,.]*\s*(bytes|KB|kB|KiB)\b[^.;]*\b(needed|of the module's budget)\b/i],
  ['a try reported', /\btried first\b|\btried,? (and )?(dropped|not kept|kept out)\b|\bnone (was |were )?kept\b/i],
  ['the time before a change', /\b(before|after) the (change|rewrite|refactor)\b/i],
  ['a figure before a rule', /\d\s*%\s*before the\b/i],
  ['a measurement reported', /\b(was|were|as) measured\b|\bmeasured on\b|\bmeasured:/i],
  ['an apology for a length', /\bover \d+ lines\b/i],
  ['a profile of the jam', /\binstructions in the jam\b/i],
];

/** The files to read, as paths relative to ROOT. */
function files() {
  const out = [];
  const walk = (rel) => {
    if (SKIP.has(rel)) return;
    for (const entry of readdirSync(join(ROOT, rel), { withFileTypes: true })) {
      const path = `${rel}/${entry.name}`;
      if (entry.isDirectory()) walk(path);
      else if (EXTENSIONS.some((e) => entry.name.endsWith(e))) out.push(path);
    }
  };
  for (const d of DIRS) {
    if (statSync(join(ROOT, d), { throwIfNoEntry: false })?.isDirectory()) walk(d);
  }
  for (const f of FILES) if (statSync(join(ROOT, f), { throwIfNoEntry: false })) out.push(f);
  return out.sort();
}

/**
 * The comment text of each line of `text` ('' where a line has none), for the comment syntax
 * of `path`. Strings are skipped so that `"//"` or `'#'` in code starts no comment.
 * @param {string} path
 * @param {string} text
 * @returns {string[]}
 */
function comments(path, text) {
  const hash = path === 'Makefile' || path.endsWith('.toml');
  const html = path.endsWith('.html');
  const lines = text.split('\n');
  const out = lines.map(() => '');
  let block = null; // the closing mark of the block comment the scan is in
  lines.forEach((line, n) => {
    let quote = null;
    for (let i = 0; i < line.length; i++) {
      if (block) {
        const end = line.indexOf(block, i);
        out[n] += end < 0 ? line.slice(i) : line.slice(i, end);
        if (end < 0) return;
        i = end + block.length - 1;
        block = null;
        continue;
      }
      const c = line[i];
      if (quote) {
        if (c === '\\') i++;
        else if (c === quote) quote = null;
        continue;
      }
      if (hash) {
        if (c === '#') {
          out[n] += line.slice(i + 1);
          return;
        }
        if (c === '"') quote = c;
        continue;
      }
      if (html && line.startsWith('<!--', i)) {
        block = '-->';
        i += 3;
      } else if (!html && line.startsWith('//', i)) {
        out[n] += line.slice(i + 2);
        return;
      } else if (!html && line.startsWith('/*', i)) {
        block = '*/';
        i += 1;
      } else if (c === '"' || c === '`' || (c === "'" && !path.endsWith('.rs'))) {
        quote = c;
      }
    }
    // A string or template literal does not run on past its line here (a long template would
    // hide the comments after it; Rust's raw strings hold no comment syntax that matters).
  });
  return out;
}

let hits = 0;
for (const path of files()) {
  const text = readFileSync(join(ROOT, path), 'utf8');
  const lines = comments(path, text);
  lines.forEach((comment, n) => {
    if (!comment.trim()) return;
    // A phrase may wrap onto the next line's comment: a hit counts on the line it starts on.
    const joined = `${comment} ${lines[n + 1] ?? ''}`;
    for (const [rule, pattern] of RULES) {
      const m = pattern.exec(joined);
      if (m && m.index < comment.length) {
        hits++;
        console.log(`${path}:${n + 1}: ${rule}: ${comment.replace(/^[/!*\s]+/, '').trim()}`);
      }
    }
  });
}
if (hits) {
  console.error(
    `${hits} comment(s) report a measurement or a history: say what the code does and why, in the present tense.`,
  );
  process.exit(1);
}
