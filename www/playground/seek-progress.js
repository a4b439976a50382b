// The progress of a long seek over the canvas of one playground: a bar, the time reached and
// the time sought, and a Cancel button (Escape does the same, input.js). The frame loop
// (loop.js) shows it once a seek has run a while, and hides it when the seek ends.

/**
 * A seek's progress as the frame loop reports it: the time reached and sought (s) and the
 * fraction of the way done.
 * @typedef {{time: number, target: number, fraction: number}} Progress
 */

export class SeekProgress {
  /**
   * @param {HTMLElement} box the progress box (template.js), holding the parts below
   * @param {() => void} cancel ends the seek where it is
   */
  constructor(box, cancel) {
    this.box = box;
    /** @type {HTMLProgressElement} */
    this.bar = box.querySelector('[data-id="seek-bar"]');
    this.text = box.querySelector('[data-id="seek-text"]');
    box.querySelector('[data-id="seek-cancel"]').addEventListener('click', cancel);
    this.shown = '';
  }

  /** Shows `progress`, or hides the box for null; writes the page only when the text changes. */
  show(/** @type {Progress | null} */ progress) {
    if (!progress) {
      if (!this.box.hidden) this.box.hidden = true;
      this.shown = '';
      return;
    }
    const percent = Math.floor(progress.fraction * 100);
    const text = `Going to t = ${progress.target.toFixed(1)} s: t = ${progress.time.toFixed(1)} s, ${percent} %`;
    if (text === this.shown) return;
    this.shown = text;
    this.text.textContent = text;
    this.bar.value = progress.fraction;
    this.box.hidden = false;
  }
}
