// dvf-playground/mdbook.js: the one script an mdBook needs, named in book.toml's
// `additional-js` as "src/dvf-playground/mdbook.js" (the package copied to the book's src/).
// mdBook includes it as a classic script, hashed, under the book's src/ path, while it copies
// the package itself (src/dvf-playground/) to the book's root: so the element is imported from
// there, found through the page's `path_to_root` (mdBook's own global), at any page depth.
// It also keeps every <dvf-playground>'s `theme` attribute in step with the book's theme:
// `light` for mdBook's light and rust themes, `dark` for coal, navy and ayu (mdBook names its
// theme as a class of <html> and swaps it when the reader picks another in the theme menu).
(() => {
  const DARK_THEMES = ['coal', 'navy', 'ayu'];
  const own = document.currentScript?.src ?? document.baseURI;
  // The book's root: mdBook's page declares `path_to_root` ("" or "../…"), a folder.
  const root = new URL(`${typeof path_to_root === 'string' ? path_to_root : ''}./`, document.baseURI).href;
  // This script's folder, relative to the book's root, without mdBook's `src/`.
  const folder = new URL('.', own).href;
  const relative = folder.startsWith(root) ? folder.slice(root.length).replace(/^src\//, '') : '';
  const url = new URL(`${relative}dvf-playground.js`, relative ? root : folder).href;

  const themeNow = () => (DARK_THEMES.some((t) => document.documentElement.classList.contains(t)) ? 'dark' : 'light');
  const apply = () => {
    const theme = themeNow();
    for (const el of document.querySelectorAll('dvf-playground')) {
      if (el.getAttribute('theme') !== theme) el.setAttribute('theme', theme);
    }
  };
  const fail = (reason) => {
    const text =
      location.protocol === 'file:'
        ? 'This figure needs the book served over HTTP, not opened from a file (file://): run "mdbook serve", or serve the book folder, e.g. "python3 -m http.server" in it.'
        : `This figure could not load ${url}: ${reason}`;
    for (const el of document.querySelectorAll('dvf-playground:not(:defined)')) el.textContent = text;
  };
  new MutationObserver(apply).observe(document.documentElement, { attributes: true, attributeFilter: ['class'] });
  const start = () => {
    apply();
    import(url).catch((e) => fail(e.message));
  };
  if (document.readyState === 'loading') document.addEventListener('DOMContentLoaded', start);
  else start();
})();
