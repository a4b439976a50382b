// dvf-playground/loader.js: a classic script that imports the element module beside it
// (dvf-playground.js), for hosts that include classic scripts only (mdBook's `additional-js`,
// a CMS's script field). It finds the module relative to its own URL, so it works at any page
// depth. When the module cannot be loaded (a page opened from file://, a missing folder), every
// <dvf-playground> on the page shows why in place of its figure.
(() => {
  const script = document.currentScript;
  const url = new URL('dvf-playground.js', script?.src || document.baseURI).href;
  const fail = (reason) => {
    const text =
      location.protocol === 'file:'
        ? 'This figure needs a page served over HTTP, not opened from a file (file://): serve the folder, e.g. run "python3 -m http.server" in it and open http://localhost:8000/.'
        : `This figure could not load ${url}: ${reason}`;
    for (const el of document.querySelectorAll('dvf-playground:not(:defined)')) {
      el.textContent = text;
      el.setAttribute('role', 'alert');
    }
  };
  import(url).catch((e) => {
    if (document.readyState === 'loading') document.addEventListener('DOMContentLoaded', () => fail(e.message));
    else fail(e.message);
  });
})();
