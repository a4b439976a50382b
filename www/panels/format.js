// How the panels write and read numbers: a value rounded to what its box shows whole, the
// exact value while the box has focus, fixed decimals without a negative zero, and a typed
// text read as a number or as what is wrong with it ("not a number", "too large").

/** Characters a box holds when it cannot be measured (not laid out): "-8.7e-7". */
const BOX_CHARS = 7;
/** The most significant digits a box shows: beyond them, the exact value on focus. */
const MAX_DIGITS = 10;

/** Measures text in a box's font, off screen. */
let measure = null;

/** `n` as text, a negative zero as "0". */
function plain(n) {
  return Object.is(n, -0) ? '0' : String(n);
}

/** `n` in exponential notation without a plus sign ("1.5e7", "-8.7e-7"). */
function exponential(n) {
  return n.toExponential().replace('e+', 'e');
}

/**
 * The texts `v` can be shown as, most precise first: rounded to MAX_DIGITS significant
 * digits down to 1, each as plain text and in exponential notation.
 */
function* candidates(v) {
  for (let p = MAX_DIGITS; p >= 1; p--) {
    const n = Number(v.toPrecision(p));
    yield plain(n);
    yield exponential(n);
  }
}

/** The room (CSS px) and font of `input`'s text, or null when it is not laid out. */
function roomOf(input) {
  if (!input?.isConnected || input.clientWidth === 0) return null;
  const style = getComputedStyle(input);
  const room = input.clientWidth - Number.parseFloat(style.paddingLeft) - Number.parseFloat(style.paddingRight);
  return { room, font: `${style.fontStyle} ${style.fontWeight} ${style.fontSize} ${style.fontFamily}` };
}

/**
 * `v` rounded to the most significant digits that `input` shows whole (its width and font;
 * BOX_CHARS characters when it is not laid out): 6.9999999999 as "7", −8.744e−7 as "-8.7e-7",
 * −0 as "0" (tests/e2e/forms.mjs, "by-number boxes"). The value itself is not changed: `exact`
 * is what the box shows on focus.
 * @param {number} v
 * @param {HTMLInputElement} [input]
 */
export function boxText(v, input) {
  if (!Number.isFinite(v)) return String(v);
  const box = roomOf(input);
  let fits = (text) => text.length <= BOX_CHARS;
  if (box) {
    measure ??= document.createElement('canvas').getContext('2d');
    measure.font = box.font;
    fits = (text) => measure.measureText(text).width <= box.room;
  }
  let last = '';
  for (const text of candidates(v)) {
    if (fits(text)) return text;
    last = text;
  }
  return last;
}

/** `v` in full: the shortest text that reads back as the same number (−0 as "0"). */
export function exact(v) {
  return plain(v);
}

/** `v` with `digits` decimals, a negative zero ("-0.00") as "0.00". */
export function fixed(v, digits) {
  const text = v.toFixed(digits);
  return /^-0\.?0*$/.test(text) ? text.slice(1) : text;
}

/**
 * The number typed in a box: `{value}`; `{empty: true}` for nothing typed; `{error}` for a
 * text that is not a number, and for one too large to be a number at all (1e400) with
 * `value` the largest number of its sign, which every field refuses with its own limit.
 * A minus sign copied from the page (U+2212) reads as "-".
 * @param {string} text
 * @returns {{value?: number, empty?: boolean, error?: string}}
 */
export function parseNumber(text) {
  const t = text.trim().replace(/\u2212/g, '-');
  if (t === '') return { empty: true };
  const n = Number(t);
  if (Number.isNaN(n)) return { error: 'not a number' };
  if (!Number.isFinite(n)) return { error: 'too large', value: Math.sign(n) * Number.MAX_VALUE };
  return { value: n };
}

/**
 * Makes `input` a box for a number that keeps what is typed (a text box with the decimal
 * keypad: a number box empties "abc" and "1e400"): it shows `boxText` of its value, and on
 * focus `exact` of it, until it is blurred or applied. `value()` is the value it stands for;
 * `input.dataset.edited` is set once the person types in it.
 * @param {HTMLInputElement} input
 * @param {() => number | null | undefined} value
 */
export function numberBox(input, value) {
  input.type = 'text';
  input.inputMode = 'decimal';
  input.autocomplete = 'off';
  input.spellcheck = false;
  input.addEventListener('focus', () => {
    const v = value();
    if (input.getAttribute('aria-invalid') !== 'true' && v != null) input.value = exact(v);
  });
  input.addEventListener('input', () => {
    input.dataset.edited = '';
  });
  input.addEventListener('blur', () => {
    if ('edited' in input.dataset || input.getAttribute('aria-invalid') === 'true') return;
    const v = value();
    if (v != null) input.value = boxText(v, input);
  });
}
