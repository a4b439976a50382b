// The camera: world centre (m) and scale (CSS px per m), equal aspect, y up on screen. Fitted
// to the scenario's bounds until the user pans or zooms; then it stays where they put it.

/** Space kept free around the scenario's bounds when fitting (CSS px): the axis labels. */
const MARGIN_PX = { left: 44, right: 14, top: 14, bottom: 26 };

/**
 * @typedef {{cx: number, cy: number, scale: number}} CameraState
 * @typedef {{
 *   scale: number, width: number, height: number,
 *   sx: (x: number) => number, sy: (y: number) => number,
 *   wx: (px: number) => number, wy: (py: number) => number,
 * }} View  world↔screen maps for a box of `width`×`height` CSS px
 */

/** The camera that places `bounds` ([xmin, ymin, xmax, ymax], m) in a `width`×`height` box. */
export function fittedCamera(bounds, width, height) {
  const [xmin, ymin, xmax, ymax] = bounds;
  const innerW = Math.max(1, width - MARGIN_PX.left - MARGIN_PX.right);
  const innerH = Math.max(1, height - MARGIN_PX.top - MARGIN_PX.bottom);
  const scale = Math.min(innerW / (xmax - xmin), innerH / (ymax - ymin));
  // The centre of the box shifted so that the margins (labels) stay clear.
  const cx = (xmin + xmax) / 2 - (MARGIN_PX.left - MARGIN_PX.right) / 2 / scale;
  const cy = (ymin + ymax) / 2 + (MARGIN_PX.top - MARGIN_PX.bottom) / 2 / scale;
  return { cx, cy, scale };
}

/**
 * The world↔screen maps of a camera in a `width`×`height` box (y up on screen).
 * @param {CameraState} camera
 * @returns {View}
 */
export function makeView(camera, width, height) {
  const { cx, cy, scale } = camera;
  const ox = width / 2 - cx * scale;
  const oy = height / 2 + cy * scale;
  return {
    scale,
    width,
    height,
    sx: (x) => ox + x * scale,
    sy: (y) => oy - y * scale,
    wx: (px) => (px - ox) / scale,
    wy: (py) => (oy - py) / scale,
  };
}

/** One playground's camera: fitted, or where the user put it. */
export class Camera {
  constructor() {
    /** @type {CameraState | null} */
    this.state = null;
    /** Whether the user panned or zoomed (then bounds no longer refit it). */
    this.user = false;
  }

  /** The view of a `width`×`height` box, refitted to `bounds` unless the user moved it. */
  view(bounds, width, height) {
    if (!this.user || !this.state) this.state = fittedCamera(bounds, width, height);
    return makeView(this.state, width, height);
  }

  /** Back to the fitted view. */
  fit() {
    this.user = false;
  }

  /** Zooms by `factor` about canvas point (px, py) of `view`: the world point there stays. */
  zoomAbout(view, factor, px, py) {
    const wx = view.wx(px);
    const wy = view.wy(py);
    const scale = this.state.scale * factor;
    this.set({ scale, cx: wx - (px - view.width / 2) / scale, cy: wy + (py - view.height / 2) / scale });
  }

  /** Moves the world with the pointer by (dx, dy) CSS px. */
  pan(view, dx, dy) {
    const s = this.state;
    this.set({ ...s, cx: s.cx - dx / view.scale, cy: s.cy + dy / view.scale });
  }

  /**
   * Two pointers: from camera `start`, where they were `distance` apart about midpoint `mid`,
   * the camera scales with their distance about their midpoint (a, b now) and follows it, in a
   * `width`×`height` box.
   */
  pinch({ start, distance, mid }, a, b, width, height) {
    const scale = start.scale * (Math.hypot(a.px - b.px, a.py - b.py) / distance);
    // The world point under the first midpoint stays under the current midpoint.
    const wx = start.cx + (mid[0] - width / 2) / start.scale;
    const wy = start.cy - (mid[1] - height / 2) / start.scale;
    const mx = (a.px + b.px) / 2;
    const my = (a.py + b.py) / 2;
    this.set({ scale, cx: wx - (mx - width / 2) / scale, cy: wy + (my - height / 2) / scale });
  }

  /** @param {CameraState} state */
  set(state) {
    this.state = state;
    this.user = true;
  }
}
