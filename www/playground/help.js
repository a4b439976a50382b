// The help overlay of one playground: the controls and keys, over the canvas.

export class Help {
  /**
   * @param {HTMLElement} panel the overlay
   * @param {HTMLElement} close its close button, focused while it is shown
   * @param {HTMLElement} canvas focused again once it is hidden
   */
  constructor(panel, close, canvas) {
    this.panel = panel;
    this.close = close;
    this.canvas = canvas;
    close.addEventListener('click', () => this.toggle(false));
  }

  /** Whether the overlay is shown. */
  get shown() {
    return !this.panel.hidden;
  }

  /** Shows the overlay, hides it, or (no `show`) toggles it. */
  toggle(show = !this.shown) {
    this.panel.hidden = !show;
    if (show) this.close.focus({ preventScroll: true });
    else this.canvas.focus({ preventScroll: true });
  }
}
