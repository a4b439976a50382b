// Pointer, wheel and keyboard input on a playground's canvas. Mouse, touch and pen through
// pointer events: drag a robot, goal, obstacle or handle (one gesture of the controller, its
// moves coalesced to one per animation frame, each predicting a shorter way ahead until the
// drag ends: Playground.setDragging), drag the background to pan, pinch with two
// fingers to zoom; the wheel zooms about the pointer; keys act anywhere inside the element but
// in a text field (and leave a focused button, menu or box the keys it uses itself), and a key
// handled here, or known here and ignored in this mode (KNOWN_KEYS), stops here: it never
// reaches the page's shortcuts.

import { addObstacleInView, addRobotInView, deleteSelection, nudgeSelection } from './actions.js';
import { hitTest } from './hit.js';
import { messageOf } from './message.js';

/** Keyboard: arrows move the selection by this fraction of the view's smaller side. */
const KEY_MOVE_FRACTION = 0.02;
/** Keyboard: Q/E turn the selection by this angle (rad). */
const KEY_TURN_RAD = Math.PI / 36;
/** The keys of a figure that is not an editor: play, step, reset, fit, zoom and the help. */
const VIEW_KEYS = [' ', 's', 'S', 'r', 'R', 'f', 'F', '+', '=', '-', '_', '?'];
/**
 * Every key the element acts on in some mode or state (the editor's included). One it does not
 * act on now (a `readonly` figure, a figure that is not an editor, an arrow with nothing
 * selected) still stops at the element, its default action kept (an arrow scrolls the page):
 * a book's shortcuts (mdBook's S for search, its arrows for the next chapter) never see it.
 * Keys it does not know (Tab, Enter, Page Down) and those with Ctrl, Meta or Alt reach the page.
 */
const KNOWN_KEYS = new Set([
  ...VIEW_KEYS,
  ...['a', 'A', 'o', 'O', 'g', 'G', 'q', 'Q', 'e', 'E', '[', ']', 'Delete', 'Backspace'],
  ...['ArrowLeft', 'ArrowRight', 'ArrowUp', 'ArrowDown'],
]);
/** Zoom factor per wheel notch or +/- key. */
const ZOOM_STEP = 1.2;

/**
 * What input uses of the controller: the canvas and its view, the selection, the edit
 * methods, the gestures, the clock, the help and the messages.
 * @typedef {Pick<import('./controller.js').Controller, 'camera' | 'canvas' | 'clock' | 'editable'
 *   | 'fit' | 'gestures' | 'help' | 'host' | 'inspect' | 'messages' | 'model' | 'moveGoal'
 *   | 'moveObstacle' | 'moveRobot' | 'pg' | 'readonly' | 'requestDraw' | 'resizeObstacle' | 'root'
 *   | 'select' | 'selection' | 'showMessage' | 'toolbar' | 'view' | 'viewChanged' | 'views'
 *   | 'zoom'>
 *   & import('./actions.js').ActionsHost & import('./hit.js').HitHost} InputHost
 */

export class Input {
  /** @param {InputHost} controller */
  constructor(controller) {
    this.c = controller;
    /** The drag in progress: its target (hit.js), pointer, grip offset (m) and last point. */
    this.drag = null;
    /** The newest pointer position of the drag, applied by the next frame. */
    this.pendingPointer = null;
    /** Pointers down on the canvas (id → canvas point), for two-finger pinch zoom. */
    this.pointers = new Map();
    this.pinch = null;
    const canvas = controller.canvas;
    canvas.addEventListener('pointerdown', (e) => this.pointerDown(e));
    canvas.addEventListener('pointermove', (e) => this.pointerMove(e));
    canvas.addEventListener('pointerup', (e) => this.pointerUp(e));
    canvas.addEventListener('pointercancel', (e) => this.pointerUp(e));
    canvas.addEventListener('wheel', (e) => this.wheel(e), { passive: false });
    // Keys anywhere inside the element (its shadow root), not only on the canvas.
    controller.root.addEventListener('keydown', (e) => this.keyDown(/** @type {KeyboardEvent} */ (e)));
  }

  /** Where the pointer is, in canvas CSS px. */
  local(e) {
    const r = this.c.canvas.getBoundingClientRect();
    return { px: e.clientX - r.left, py: e.clientY - r.top };
  }

  pointerDown(e) {
    const c = this.c;
    // A figure (no `controls`, or `readonly`) is not an editor: nothing to drag.
    if (!c.pg || e.button > 0 || !c.editable) return;
    c.canvas.focus({ preventScroll: true });
    const { px, py } = this.local(e);
    this.pointers.set(e.pointerId, { px, py });
    if (this.pointers.size === 2) {
      // A second finger: whatever the first started becomes a pinch (zoom and pan).
      this.cancelDrag();
      const [a, b] = [...this.pointers.values()];
      c.view();
      this.pinch = {
        distance: Math.hypot(a.px - b.px, a.py - b.py) || 1,
        start: { ...c.camera.state },
        mid: [(a.px + b.px) / 2, (a.py + b.py) / 2],
      };
      return;
    }
    if (this.pointers.size > 2) return;
    const target = hitTest(c, px, py);
    let anchor = [0, 0];
    if (target.kind === 'robot' || target.kind === 'goal' || target.kind === 'obstacle') {
      c.select({ kind: target.kind, index: target.index });
      if (target.kind !== 'obstacle') c.inspect(target.index);
      if (target.kind === 'robot') anchor = c.views.pose(target.index);
      if (target.kind === 'goal') anchor = c.model.robots[target.index].goal;
      if (target.kind === 'obstacle') anchor = c.model.obstacles[target.index].center;
    }
    const view = c.view();
    this.drag = {
      ...target,
      pointerId: e.pointerId,
      offset: [view.wx(px) - anchor[0], view.wy(py) - anchor[1]],
      last: { px, py },
      moved: false,
    };
    if (target.kind !== 'pan') {
      c.gestures.begin();
      // The drag's edits look a shorter way ahead in a scene of many robots; its end, in full.
      c.pg.setDragging(true);
    }
    c.canvas.setPointerCapture(e.pointerId);
    c.toolbar.update();
    c.requestDraw();
  }

  pointerMove(e) {
    if (this.pointers.has(e.pointerId)) this.pointers.set(e.pointerId, this.local(e));
    if (this.pinch && this.pointers.size === 2) {
      const [a, b] = [...this.pointers.values()];
      const canvas = this.c.canvas;
      this.c.camera.pinch(this.pinch, a, b, canvas.clientWidth, canvas.clientHeight);
      this.c.requestDraw();
      return;
    }
    if (!this.drag || e.pointerId !== this.drag.pointerId) return;
    // Coalesced: the newest position is applied once per animation frame.
    this.pendingPointer = this.local(e);
    this.c.requestDraw();
  }

  pointerUp(e) {
    const c = this.c;
    this.pointers.delete(e.pointerId);
    if (this.pinch) {
      if (this.pointers.size < 2) this.pinch = null;
      c.viewChanged();
      if (c.canvas.hasPointerCapture(e.pointerId)) c.canvas.releasePointerCapture(e.pointerId);
      return;
    }
    if (!this.drag || e.pointerId !== this.drag.pointerId) return;
    this.applyPending();
    const d = this.drag;
    this.drag = null;
    if (c.canvas.hasPointerCapture(e.pointerId)) c.canvas.releasePointerCapture(e.pointerId);
    if (d.kind !== 'pan') {
      this.endDragging();
      if (d.moved) c.gestures.commit(d.kind);
      else c.gestures.cancel();
    }
    c.messages.clear('drag');
    c.viewChanged();
    c.requestDraw();
  }

  /** Ends a drag without keeping it: the scene goes back to where the drag began. */
  cancelDrag() {
    const d = this.drag;
    if (!d) return;
    this.drag = null;
    this.pendingPointer = null;
    if (d.kind !== 'pan') {
      this.c.gestures.cancel();
      this.endDragging();
    }
  }

  /** The drag's end: the prediction its edits shortened is made again in full. */
  endDragging() {
    this.c.pg.setDragging(false);
    this.c.views.refresh();
  }

  /** Applies the drag's newest pointer position, if it moved since the last frame. */
  applyPending() {
    const p = this.pendingPointer;
    if (!p) return;
    this.pendingPointer = null;
    this.applyDrag(p);
  }

  /** Applies the drag in progress for the pointer at canvas point (px, py). */
  applyDrag({ px, py }) {
    const c = this.c;
    const d = this.drag;
    if (!d) return;
    const view = c.view();
    const wx = view.wx(px);
    const wy = view.wy(py);
    d.moved = true;
    if (d.kind === 'pan') {
      c.camera.pan(view, px - d.last.px, py - d.last.py);
      d.last = { px, py };
      return;
    }
    const i = d.index;
    // Where the grip is now, in the world.
    const gx = wx - d.offset[0];
    const gy = wy - d.offset[1];
    try {
      if (d.kind === 'robot') {
        c.moveRobot(i, gx, gy, c.views.pose(i)[2]);
      } else if (d.kind === 'robot-heading') {
        const [x, y] = c.views.pose(i);
        c.moveRobot(i, x, y, Math.atan2(wy - y, wx - x));
      } else if (d.kind === 'goal') {
        c.moveGoal(i, gx, gy, c.model.robots[i].goal[2]);
      } else if (d.kind === 'goal-heading') {
        const g = c.model.robots[i].goal;
        c.moveGoal(i, g[0], g[1], Math.atan2(wy - g[1], wx - g[0]));
      } else if (d.kind === 'obstacle') {
        c.moveObstacle(i, gx, gy);
      } else if (d.kind === 'obstacle-radius') {
        const o = c.model.obstacles[i];
        const r = Math.max(Math.hypot(wx - o.center[0], wy - o.center[1]), 1e-3);
        // The ring keeps its width when the disc would grow past it.
        c.resizeObstacle(i, r, o.influence <= r ? r + (o.influence - o.radius) : o.influence);
      } else if (d.kind === 'obstacle-influence') {
        const o = c.model.obstacles[i];
        c.resizeObstacle(i, o.radius, Math.max(Math.hypot(wx - o.center[0], wy - o.center[1]), o.radius * 1.01));
      }
      c.messages.clear('drag');
    } catch (e) {
      // Over the canvas, so the view does not move; gone once the drag ends (the scene keeps
      // its last valid position).
      c.showMessage(messageOf(e), { source: 'drag' });
    }
  }

  wheel(e) {
    const c = this.c;
    // Embedded in text, the wheel scrolls the page unless the canvas has been clicked
    // (focused) or Ctrl is held; with the full controls it always zooms.
    const mine = c.host.hasAttribute('controls') || e.ctrlKey || c.root.activeElement === c.canvas;
    if (!mine) return;
    e.preventDefault();
    const { px, py } = this.local(e);
    c.zoom(e.deltaY < 0 ? ZOOM_STEP : 1 / ZOOM_STEP, px, py);
  }

  /** Whether the focused part `target` needs key `e` itself (typing, a button's Space). */
  static ownsKey(target, e) {
    const tag = target?.tagName;
    const mod = e.ctrlKey || e.metaKey;
    if (tag === 'TEXTAREA' || target?.isContentEditable) return true;
    if (tag === 'INPUT') return target.type !== 'checkbox' || e.key === ' ';
    if (tag === 'SELECT') return !mod && e.key !== 'Delete' && e.key !== 'Escape';
    if (tag === 'BUTTON') return e.key === ' ' || e.key === 'Enter';
    return false;
  }

  keyDown(e) {
    const c = this.c;
    if (e.defaultPrevented) return;
    // Escape ends a seek under way, wherever the focus is (the scrubber that started it
    // included) and in every mode; the progress bar's Cancel does the same.
    const endsSeek = e.key === 'Escape' && c.clock.seeking();
    if (endsSeek) c.clock.cancelSeek();
    // A focused field, menu or button keeps the keys it uses.
    else if (Input.ownsKey(e.composedPath()[0], e)) return;
    if (endsSeek || this.act(e)) {
      // A key the figure used is its own: the host page's shortcuts never see it.
      e.preventDefault();
      e.stopPropagation();
      c.viewChanged();
      c.toolbar.update();
      c.requestDraw();
    } else if (!e.ctrlKey && !e.metaKey && !e.altKey && KNOWN_KEYS.has(e.key)) {
      e.stopPropagation();
    }
  }

  /** Does what key `e` asks in this mode and state; false when it does nothing. */
  act(e) {
    const c = this.c;
    const mod = e.ctrlKey || e.metaKey;
    const key = e.key;
    // A readonly figure takes no key.
    if (!c.pg || c.readonly) return false;
    // A figure that is not an editor takes the clock's, the view's and the help's keys only.
    if (!c.editable && !VIEW_KEYS.includes(key) && !(key === 'Escape' && c.help.shown)) return false;
    const centre = () => [c.canvas.clientWidth / 2, c.canvas.clientHeight / 2];
    let handled = true;
    if (mod && (key === 'z' || key === 'Z')) {
      if (e.shiftKey) c.gestures.redo();
      else c.gestures.undo();
    } else if (mod && key === 'y') c.gestures.redo();
    else if (mod) handled = false;
    else if (key === ' ') c.clock.togglePlay();
    else if (key === 's' || key === 'S') c.clock.stepTime();
    else if (key === 'r' || key === 'R') c.clock.reset();
    else if (key === 'a' || key === 'A') addRobotInView(c);
    else if (key === 'o' || key === 'O') addObstacleInView(c);
    else if (key === 'Delete' || key === 'Backspace') deleteSelection(c);
    else if (key === 'f' || key === 'F') c.fit();
    else if (key === '+' || key === '=') c.zoom(ZOOM_STEP, ...centre());
    else if (key === '-' || key === '_') c.zoom(1 / ZOOM_STEP, ...centre());
    else if (key === '[' || key === ']') this.cycleSelection(key === ']' ? 1 : -1);
    else if (key === 'g' || key === 'G') this.toggleGoalSelection();
    else if (key === '?') c.help.toggle();
    else if (key === 'Escape' && c.help.shown) c.help.toggle(false);
    else if (key === 'Escape') c.select(null);
    else if (key.startsWith('Arrow') && c.selection) {
      const view = c.view();
      const stepM = (KEY_MOVE_FRACTION * Math.min(view.width, view.height)) / view.scale;
      const dx = key === 'ArrowLeft' ? -stepM : key === 'ArrowRight' ? stepM : 0;
      const dy = key === 'ArrowDown' ? -stepM : key === 'ArrowUp' ? stepM : 0;
      nudgeSelection(c, dx, dy, 0);
    } else if ((key === 'q' || key === 'Q' || key === 'e' || key === 'E') && c.selection) {
      nudgeSelection(c, 0, 0, key.toLowerCase() === 'q' ? KEY_TURN_RAD : -KEY_TURN_RAD);
    } else handled = false;
    return handled;
  }

  /** Selects the next (`dir` 1) or previous (−1) robot, and inspects it. */
  cycleSelection(dir) {
    const c = this.c;
    const n = c.model.robots.length;
    const i = c.selection && c.selection.kind !== 'obstacle' ? (c.selection.index + dir + n) % n : 0;
    c.select({ kind: 'robot', index: i });
    c.inspect(i);
  }

  /** Switches the selection between a robot and its goal. */
  toggleGoalSelection() {
    const c = this.c;
    const sel = c.selection;
    if (!sel || sel.kind === 'obstacle') return;
    c.select({ kind: sel.kind === 'robot' ? 'goal' : 'robot', index: sel.index });
  }
}
