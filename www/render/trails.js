// The trails travelled: a layer of their own, brought up to date each frame.

import { POSE_STRIDE } from '../playground/wasm-views.js';
import { CROWD_STYLE_ABOVE, hairline, ROBOT_COLOURS, TRAIL_WIDTH_PX } from './theme.js';

/** A full redraw of the trails skips points closer than this to the last one drawn (CSS px). */
const TRAIL_DECIMATE_PX = 1;
/**
 * While the view moves, trails that took longer than TRAIL_DEFER_MS to draw are shown
 * stretched from their last drawing, and drawn again once the view has been still for
 * TRAIL_SETTLE_MS.
 */
const TRAIL_DEFER_MS = 12;
export const TRAIL_SETTLE_MS = 150;

/**
 * The trails, kept on a canvas of their own that is brought up to date each frame: while the
 * view stays put only the samples recorded since the last frame are drawn (a few segments
 * per robot), so trails cost O(robots) per frame however long they are. A new view, size,
 * scene or ring layout redraws them all, one path per colour, points closer than
 * TRAIL_DECIMATE_PX to the previous one skipped.
 *
 * Sample `g` (counting from the last reset, `scene.recorded` in all) lies in ring slot
 * `g % cap`; robot `i` holds its last `trailLens[i]` samples.
 */
export class TrailLayer {
  constructor() {
    this.canvas = document.createElement('canvas');
    this.state = { width: 0, height: 0, scale: 0, ox: 0, oy: 0, generation: -1, robots: -1, cap: -1, drawn: 0 };
    /** The camera of the last frame and when it last changed (ms). */
    this.seen = { scale: 0, ox: 0, oy: 0, at: 0 };
    /** How long the last full drawing took (ms). */
    this.costMs = 0;
    /** Whether the layer shows an older view (a redraw is due once the view is still). */
    this.stale = false;
  }

  /**
   * Updates the layer for `view` (a makeView) and `scene` at devicePixelRatio `dpr`; `nowMs`
   * is the frame's time.
   */
  update(view, scene, dpr, generation, nowMs) {
    const bw = Math.max(1, Math.round(view.width * dpr));
    const bh = Math.max(1, Math.round(view.height * dpr));
    const n = scene.scenario.robots.length;
    const cap = scene.trailCapacity;
    const st = this.state;
    const recorded = scene.recorded;
    const ox = view.sx(0);
    const oy = view.sy(0);
    const seen = this.seen;
    if (seen.scale !== view.scale || seen.ox !== ox || seen.oy !== oy)
      Object.assign(seen, { scale: view.scale, ox, oy, at: nowMs });
    const sameScene =
      st.width === bw &&
      st.height === bh &&
      st.generation === generation &&
      st.robots === n &&
      st.cap === cap &&
      recorded >= st.drawn &&
      recorded - st.drawn < cap;
    const sameCamera = st.scale === view.scale && st.ox === ox && st.oy === oy;
    const ctx = this.canvas.getContext('2d');
    const crowd = n > CROWD_STYLE_ABOVE;
    this.stale = false;
    if (sameScene && !sameCamera && this.costMs > TRAIL_DEFER_MS && nowMs - seen.at < TRAIL_SETTLE_MS) {
      this.stale = true;
      return;
    }
    if (!sameScene || !sameCamera) {
      const t0 = performance.now();
      if (this.canvas.width !== bw) this.canvas.width = bw;
      if (this.canvas.height !== bh) this.canvas.height = bh;
      ctx.setTransform(1, 0, 0, 1, 0, 0);
      ctx.clearRect(0, 0, bw, bh);
      ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
      this.draw(ctx, view, scene, 0, crowd);
      Object.assign(st, { width: bw, height: bh, scale: view.scale, ox, oy, generation, robots: n, cap });
      this.costMs = performance.now() - t0;
    } else if (recorded > st.drawn) {
      ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
      this.draw(ctx, view, scene, st.drawn - 1, crowd);
    }
    st.drawn = recorded;
  }

  /** Puts the layer on `ctx`, stretched from the view it was drawn in to `view`. */
  composite(ctx, view) {
    const st = this.state;
    if (st.scale === 0) return;
    const r = view.scale / st.scale;
    const w = view.width * r;
    const h = view.height * r;
    ctx.drawImage(this.canvas, view.sx(0) - st.ox * r, view.sy(0) - st.oy * r, w, h);
  }

  /** Draws every robot's trail from global sample `from` on (the first kept one at least). */
  draw(ctx, view, scene, from, crowd) {
    const n = scene.scenario.robots.length;
    const cap = scene.trailCapacity;
    const t = scene.trails;
    const lens = scene.trailLens;
    const end = scene.recorded;
    const k = ROBOT_COLOURS.length;
    const full = from <= 0;
    // A crowd's trails are hairlines (the rasteriser's fast path; see THIN_PREDICTED_ABOVE in theme.js).
    ctx.lineWidth = crowd ? hairline(scene.dpr) : TRAIL_WIDTH_PX;
    ctx.lineJoin = 'round';
    ctx.lineCap = 'round';
    for (let c = 0; c < k; c++) {
      ctx.beginPath();
      for (let i = c; i < n; i += k) {
        const first = Math.max(from, end - lens[i]);
        if (end - first < 2) continue;
        const base = i * cap * POSE_STRIDE;
        let o = base + (first % cap) * POSE_STRIDE;
        let lx = view.sx(t[o]);
        let ly = view.sy(t[o + 1]);
        ctx.moveTo(lx, ly);
        for (let g = first + 1; g < end; g++) {
          o = base + (g % cap) * POSE_STRIDE;
          const x = view.sx(t[o]);
          const y = view.sy(t[o + 1]);
          // Skipping only on a full redraw, and never the newest point, where the next
          // frame's segments start.
          if (full && g < end - 1 && Math.abs(x - lx) < TRAIL_DECIMATE_PX && Math.abs(y - ly) < TRAIL_DECIMATE_PX)
            continue;
          ctx.lineTo(x, y);
          lx = x;
          ly = y;
        }
      }
      ctx.strokeStyle = ROBOT_COLOURS[c];
      ctx.stroke();
    }
  }
}
