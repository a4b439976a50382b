// The one DOM helper of the panels. Text is always set with textContent, never as HTML.

/** A new `tag` element with `text` (as text) and `className`, when given. */
export function el(tag, text, className) {
  const e = document.createElement(tag);
  if (text !== undefined) e.textContent = text;
  if (className) e.className = className;
  return e;
}
