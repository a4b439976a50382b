// dvf-playground/mdbook.js: a classic script for mdBook's `additional-js` that keeps every
// <dvf-playground>'s `theme` attribute in step with the book's theme: `light` for mdBook's
// light and rust themes, `dark` for coal, navy and ayu. mdBook names its theme as a class of
// <html> and swaps it when the reader picks another in the theme menu.
(() => {
  const DARK_THEMES = ['coal', 'navy', 'ayu'];
  const themeNow = () => (DARK_THEMES.some((t) => document.documentElement.classList.contains(t)) ? 'dark' : 'light');
  const apply = () => {
    const theme = themeNow();
    for (const el of document.querySelectorAll('dvf-playground')) {
      if (el.getAttribute('theme') !== theme) el.setAttribute('theme', theme);
    }
  };
  new MutationObserver(apply).observe(document.documentElement, { attributes: true, attributeFilter: ['class'] });
  if (document.readyState === 'loading') document.addEventListener('DOMContentLoaded', apply);
  else apply();
})();
