// Gestures and their undo: what a person does (a drag, a key, a button, a field) is begin(),
// any number of edits, commit(kind): one undo entry (the scenario text before its first edit,
// if it changed; history.js) and one `change` event. Undo and redo apply a kept scenario text
// as one edit of the whole scene.

import { History } from './history.js';
import { messageOf } from './message.js';

/**
 * What the gestures read and whom they tell.
 * @typedef {{
 *   hasScene: () => boolean,
 *   text: () => string,
 *   reread: () => void,
 *   apply: (scenario: any) => void,
 *   showMessage: (text: string) => void,
 *   filled: () => void,
 *   shown: () => void,
 *   emit: (kind: string) => void,
 * }} GestureHost
 *   whether there is a scene; the scenario's JSON text; reading the core's scenario again into
 *   the model; replacing the scene by a scenario (throws the core's Error); the message over
 *   the canvas; the panel filled anew; the toolbar updated; the `change` event of a kind
 */

export class Gestures {
  /** @param {GestureHost} host */
  constructor(host) {
    this.host = host;
    this.history = new History();
  }

  /** Starts a gesture (a drag, a key, a button); one begun within another joins it. */
  begin() {
    this.history.begin();
  }

  /** Ends the gesture: one undo entry if it changed the scenario, one `change` event of `kind`. */
  commit(kind) {
    const before = this.history.end();
    if (before) {
      this.host.reread();
      if (this.host.text() !== before) this.history.push(before);
      this.host.shown();
    }
    this.host.emit(kind);
  }

  /** Ends the gesture without keeping it: the scenario goes back to where it began. */
  cancel() {
    const before = this.history.end();
    if (!before || this.host.text() === before) return;
    this.#apply(before);
  }

  /**
   * One gesture of the edits `edits()` makes, of `kind`: on an error shows the message, keeps
   * the scene and returns false.
   */
  change(kind, edits) {
    this.begin();
    try {
      edits();
    } catch (e) {
      this.cancel();
      this.host.showMessage(messageOf(e));
      return false;
    }
    this.host.showMessage('');
    this.commit(kind);
    return true;
  }

  undo() {
    this.#travel('undo');
  }

  redo() {
    this.#travel('redo');
  }

  /** @param {'undo' | 'redo'} direction */
  #travel(direction) {
    if (!this.host.hasScene()) return;
    if (this.history.travel(direction, this.host.text, (text) => this.#apply(text))) {
      this.host.filled();
      this.host.emit(direction);
    }
    this.host.shown();
  }

  /** Applies scenario text `text` (from the history); false with the message when refused. */
  #apply(text) {
    try {
      this.host.apply(JSON.parse(text));
      this.host.showMessage('');
      return true;
    } catch (e) {
      this.host.showMessage(messageOf(e));
      return false;
    }
  }
}
