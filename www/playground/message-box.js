// The message over the canvas of one playground: an error or a notice, as text (never HTML),
// with buttons beside it, until the user acts or a newer message replaces it.

export class MessageBox {
  /**
   * @param {{box: HTMLElement, text: HTMLElement, actions: HTMLElement, close: HTMLElement}} parts
   *   the box, its text, the row of its buttons and its × button
   */
  constructor({ box, text, actions, close }) {
    this.parts = { box, text, actions };
    /** What showed the message now (show's `source`), empty when none or hidden. */
    this.source = '';
    close.addEventListener('click', () => this.show(''));
  }

  /**
   * Shows `text` until the user acts (an edit, a load, the × button) or a newer message
   * replaces it; empty hides it. `info` marks a notice rather than an error; `actions` are
   * buttons `[label, run]` beside the text; `source` names what showed it, for clear.
   * @param {string} text
   * @param {{info?: boolean, actions?: [string, () => void][], source?: string}} [options]
   */
  show(text, { info = false, actions = [], source = '' } = {}) {
    const { box, actions: row } = this.parts;
    this.parts.text.textContent = text ?? '';
    const buttons = actions.map(([label, run]) => {
      const b = document.createElement('button');
      b.type = 'button';
      b.textContent = label;
      b.addEventListener('click', () => {
        this.show('');
        run();
      });
      return b;
    });
    row.replaceChildren(...buttons);
    box.classList.toggle('info', info);
    box.hidden = !text;
    this.source = text ? source : '';
  }

  /** Hides the message if `source` showed it. */
  clear(source) {
    if (this.source === source) this.show('');
  }

  /** Replaces the text of the message that `source` showed (a progress), if it is still shown. */
  update(source, text) {
    if (this.source === source) this.parts.text.textContent = text;
  }
}
