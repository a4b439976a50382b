import 'dvf-playground';

// The package's declarations put <dvf-playground> in HTMLElementTagNameMap: `figure` is a
// DvfPlayground, and its events carry typed details.
const figure = document.querySelector('dvf-playground');
const time = document.querySelector('output');
figure?.addEventListener('tick', (event) => {
  if (time) time.textContent = event.detail.time.toFixed(2);
});
