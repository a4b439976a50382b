// Undo and redo of the scenario (the document): starts, goals, obstacles, parameters, robots
// and obstacles added or deleted, presets and imports. An entry is the scenario's JSON text
// as it was before a gesture (a drag, a key, a button: see playground/gestures.js), kept
// when the gesture's first edit comes; moving a robot at t > 0 nudges the running simulation
// and is no entry.

/** Undo keeps at most this many scenarios, and at most UNDO_CHARS characters of them. */
const UNDO_LIMIT = 200;
const UNDO_CHARS = 32 * 1024 * 1024;

export class History {
  constructor() {
    /** @type {string[]} */
    this.undoStack = [];
    /** @type {string[]} */
    this.redoStack = [];
    /** @type {{before: string | null, depth: number} | null} the gesture in progress */
    this.gesture = null;
  }

  get canUndo() {
    return this.undoStack.length > 0;
  }

  get canRedo() {
    return this.redoStack.length > 0;
  }

  /** Starts a gesture; one begun within another joins it. */
  begin() {
    if (this.gesture) this.gesture.depth += 1;
    else this.gesture = { before: null, depth: 0 };
  }

  /** Before the scenario changes: a gesture keeps `text()`, the scenario as it was, once. */
  willChange(text) {
    const g = this.gesture;
    if (g && g.before === null) g.before = text();
  }

  /**
   * Ends a gesture. The outermost one returns the scenario text it kept, null if nothing
   * changed; one within another returns null (the outer one keeps the text).
   */
  end() {
    const g = this.gesture;
    if (!g) return null;
    if (g.depth > 0) {
      g.depth -= 1;
      return null;
    }
    this.gesture = null;
    return g.before;
  }

  /** Forgets everything (a new document). */
  clear() {
    this.undoStack = [];
    this.redoStack = [];
  }

  /** Records `before`, the scenario text an edit replaced; a new edit forgets what was undone. */
  push(before) {
    this.undoStack.push(before);
    let chars = this.undoStack.reduce((sum, t) => sum + t.length, 0);
    while (this.undoStack.length > 1 && (this.undoStack.length > UNDO_LIMIT || chars > UNDO_CHARS)) {
      chars -= this.undoStack.shift().length;
    }
    this.redoStack = [];
  }

  /**
   * Steps back (`undo`) or forward: `apply(text)` applies the scenario text popped and returns
   * whether it could; `now()` is the scenario text it replaces, kept to travel back. Returns
   * whether the step happened.
   * @param {'undo' | 'redo'} direction
   * @param {() => string} now
   * @param {(text: string) => boolean} apply
   */
  travel(direction, now, apply) {
    const [from, to] = direction === 'undo' ? [this.undoStack, this.redoStack] : [this.redoStack, this.undoStack];
    if (!from.length) return false;
    const text = from.pop();
    const current = now();
    if (!apply(text)) {
      from.push(text);
      return false;
    }
    to.push(current);
    return true;
  }
}
