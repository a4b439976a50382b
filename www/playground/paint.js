// One frame's picture of a playground: the scene on its canvas (with the field overlay, the
// trail layer and the crowd's sprites, the marks of the run's violations), the clock, title and hint over it, and with the
// controls the plots and the inspected robot's line in the side panel.

import { showInspected } from '../panels/inspected.js';
import { PlotsPanel } from '../panels/plots.js';
import { fitCanvas } from '../render/canvas.js';
import { drawViolationMarks } from '../render/marks.js';
import { drawScene } from '../render/scene.js';
import { drawGhost } from './ghost.js';
import { SpriteLayer } from '../render/sprites.js';
import { SvgContext } from '../render/svg.js';
import { FIELD_SPACING_PX, readPalette, setPalette } from '../render/theme.js';
import { TRAIL_SETTLE_MS, TrailLayer } from '../render/trails.js';
import { fixed } from '../panels/format.js';
import { messageOf } from './message.js';

/** At most this many field arrows per side. */
const MAX_FIELD_SIDE = 60;
/** The stamp of a picture or a recording (stamp). */
const STAMP_FONT = '600 13px system-ui, sans-serif';
/** Integral curves start from an n × n grid over the scenario's bounds. */
const CURVE_GRID = 9;

/** The title and the time in the top-left corner of a picture or a recording. */
function stamp(ctx, title, clock) {
  ctx.save();
  ctx.font = STAMP_FONT;
  ctx.textBaseline = 'top';
  const text = `${title} · ${clock}`;
  const w = ctx.measureText(text).width;
  ctx.fillStyle = 'rgba(255, 255, 255, 0.85)';
  ctx.fillRect(6, 6, w + 12, 22);
  ctx.fillStyle = '#111827';
  ctx.fillText(text, 12, 10);
  ctx.restore();
}

/** The clock of frame `scene`: its time and the run's duration. */
function clockText(scene) {
  return `t = ${scene.time.toFixed(2)} s / ${scene.duration.toFixed(2)} s`;
}

/**
 * What the painter reads of the controller: the state a frame shows, and the parts whose
 * per-frame text it updates.
 * @typedef {Pick<import('./controller.js').Controller, '$' | 'canvas' | 'fieldMode' | 'focusRobot'
 *   | 'compare' | 'generation' | 'host' | 'input' | 'limits' | 'loop' | 'model' | 'pg' | 'pin'
 *   | 'recorder' | 'requestDraw' | 'results' | 'selection' | 'selectionPanel' | 'showMessage'
 *   | 'showSensing' | 'theta0' | 'toolbar' | 'view' | 'views'>} PaintHost
 */

export class Painter {
  /** @param {PaintHost} controller */
  constructor(controller) {
    this.c = controller;
    this.trailLayer = new TrailLayer();
    this.spriteLayer = new SpriteLayer();
    this.plots = new PlotsPanel(controller.$('plots'));
    /** The scene's colours from the stylesheet (render/theme.js), read by readTheme. */
    this.palette = readPalette(controller.$('canvas').closest('.pg'));
    /** The integral curves drawn, and what they were computed for. */
    this.curves = null;
    this.curvesKey = '';
    /** @type {ReturnType<typeof setTimeout> | null} */
    this.settleTimer = null;
  }

  /** A new simulation: the curves are computed anew. */
  newScene() {
    this.curvesKey = '';
  }

  /**
   * Reads the colours of `node` (the element's `.pg`) in the `dark` theme or the light one:
   * the painters', the plots', and the crowd's sprites drawn anew (the controller redraws the
   * trails).
   */
  readTheme(node, dark) {
    node.classList.toggle('dark', dark);
    this.palette = readPalette(node);
    setPalette(this.palette);
    const p = this.palette;
    this.plots.colours = { text: p.plotText, axis: p.plotAxis, pair: p.plotPair };
    this.spriteLayer = new SpriteLayer();
  }

  /**
   * Draws the frame on the canvas, or with `target` on another canvas at density `dpr` (a
   * PNG, record.js) with the title and the time stamped in, as in a recording.
   * @param {{canvas: HTMLCanvasElement, dpr: number} | null} [target]
   */
  draw(target = null) {
    const c = this.c;
    // The module's colours are shared by every playground of the page: this one's, now.
    setPalette(this.palette);
    const { ctx, width, height } = target
      ? fitCanvas(target.canvas, target.dpr, [c.canvas.clientWidth, c.canvas.clientHeight])
      : fitCanvas(c.canvas);
    const view = c.view();
    const scene = this.scene(view, width, height, ctx.canvas.width / width);
    this.trailLayer.update(view, scene, scene.dpr, c.generation, performance.now());
    if (this.trailLayer.stale && !this.settleTimer) {
      // The trails are shown stretched while the view moves: draw them anew once it rests.
      this.settleTimer = setTimeout(() => {
        this.settleTimer = null;
        c.requestDraw();
      }, TRAIL_SETTLE_MS);
    }
    drawScene(ctx, view, scene, this.underlay(ctx, view, scene.time));
    drawViolationMarks(ctx, view, c.results.marks, scene.time);
    const loop = c.loop;
    const slowed =
      loop.playing && loop.rate < loop.speed * 0.995
        ? ` (${loop.rate.toPrecision(2)}× real time: the crowd steps slower than the clock)`
        : '';
    const state = loop.playing
      ? slowed
      : loop.seekStep != null
        ? ' (going there…)'
        : loop.convergedAt != null
          ? ' (stopped: every robot at its goal)'
          : ' (paused)';
    const clock = clockText(scene);
    if (target || c.recorder.active) stamp(ctx, c.model.name, clock);
    if (target) return;
    c.$('clock').textContent = `${clock}${state}`;
    c.toolbar.showTime(scene.time, scene.duration);
    c.$('hint').textContent = this.hintText();
    // Free text from the scenario: textContent only, never HTML.
    c.$('title').textContent = c.model.name;
    if (c.host.hasAttribute('controls')) {
      this.plots.draw(scene, c.focusRobot, c.pin.ghost);
      showInspected(c.$('robot-info'), c.focusRobot, c.model.robots.length, scene.status);
      c.selectionPanel.update();
    }
  }

  /**
   * What a frame of `view` (`width × height` CSS px at density `dpr`) draws (render/scene.js),
   * read after every other call into wasm of the frame (a view of wasm memory is valid until
   * the memory grows).
   * @returns {import('../render/scene.js').Scene}
   */
  scene(view, width, height, dpr) {
    const c = this.c;
    const fieldLength = c.fieldMode === 'arrows' ? this.sampleField(view, width, height) : 0;
    const curves = c.fieldMode === 'curves' ? this.integralCurves() : null;
    return {
      ...c.views.read(),
      scenario: c.model,
      selection: c.selection,
      focusRobot: c.focusRobot,
      showSensing: c.showSensing,
      field: fieldLength ? c.views.field(fieldLength) : null,
      curves,
      curvePoints: c.limits.curvePoints,
      trailLayer: this.trailLayer,
      spriteLayer: this.spriteLayer,
      dpr,
    };
  }

  /**
   * The frame as an SVG document (render/svg.js): what the canvas shows, as vectors (trails,
   * predicted paths, obstacles, robots, grid and labels), the title and the time stamped in.
   */
  svg() {
    const c = this.c;
    setPalette(this.palette);
    const width = c.canvas.clientWidth;
    const height = c.canvas.clientHeight;
    const ctx = new SvgContext(width, height);
    const view = c.view();
    const scene = { ...this.scene(view, width, height, 1), vector: true };
    const g = /** @type {any} */ (ctx);
    drawScene(g, view, scene, this.underlay(g, view, scene.time));
    drawViolationMarks(g, view, c.results.marks, scene.time);
    stamp(g, c.model.name, clockText(scene));
    return ctx.toString();
  }

  /**
   * What is drawn under the scene's marks, over its grid: the pinned run's paths (ghost.js) and
   * the compared planner's run at time `time` (compare.js).
   */
  underlay(ctx, view, time) {
    const c = this.c;
    return () => {
      if (c.pin.ghost) drawGhost(ctx, view, c.pin.ghost);
      c.compare.draw(ctx, view, time);
    };
  }

  hintText() {
    const c = this.c;
    if (c.input.drag) return '';
    const robot = c.focusRobot + 1;
    if (c.fieldMode === 'curves')
      return `integral curves of robot ${robot}'s goal field from θ(0) = ${fixed(c.theta0, 2)} rad`;
    if (c.fieldMode === 'arrows') return `arrows: the field Γ of robot ${robot} at its current heading`;
    return '';
  }

  /**
   * Samples the inspected robot's field over the view into wasm memory (read it with
   * `views.field`); returns the count of values, 0 with the message on error.
   */
  sampleField(view, width, height) {
    const c = this.c;
    const nx = Math.min(MAX_FIELD_SIDE, Math.max(2, Math.floor(width / FIELD_SPACING_PX)));
    const ny = Math.min(MAX_FIELD_SIDE, Math.max(2, Math.floor(height / FIELD_SPACING_PX)));
    const hx = width / nx / 2;
    const hy = height / ny / 2;
    try {
      return c.pg.refreshField(
        c.focusRobot,
        view.wx(hx),
        view.wy(height - hy),
        view.wx(width - hx),
        view.wy(hy),
        nx,
        ny,
      );
    } catch (e) {
      c.showMessage(messageOf(e));
      return 0;
    }
  }

  /**
   * The inspected robot's integral curves, computed again only when the robot, its goal, θ(0)
   * or the bounds change; null with the message on error.
   */
  integralCurves() {
    const c = this.c;
    const s = c.model;
    const g = s.robots[c.focusRobot]?.goal;
    const key = JSON.stringify([c.focusRobot, g, c.theta0, s.bounds]);
    if (key !== this.curvesKey) {
      const [x0, y0, x1, y1] = s.bounds;
      try {
        this.curves = c.pg.integralCurves(c.focusRobot, c.theta0, x0, y0, x1, y1, CURVE_GRID);
      } catch (e) {
        c.showMessage(messageOf(e));
        this.curves = null;
      }
      this.curvesKey = key;
    }
    return this.curves;
  }
}
