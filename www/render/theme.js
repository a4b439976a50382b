// The look of the scene and its legend: colours, line widths, dash patterns, glyph sizes and
// fonts, in one place. Sizes are CSS pixels.

/**
 * One colour per robot, cycled: Tableau 10 (distinct, legible on white and on dark grey), then
 * ten more of other hues and lightness, so that colours repeat only after twenty robots.
 */
export const ROBOT_COLOURS = [
  '#4e79a7',
  '#f28e2b',
  '#e15759',
  '#76b7b2',
  '#59a14f',
  '#edc948',
  '#b07aa1',
  '#ff9da7',
  '#9c755f',
  '#17becf',
  '#1f3d7a',
  '#a0522d',
  '#7b1fa2',
  '#2e7d32',
  '#c2185b',
  '#00838f',
  '#9e9d24',
  '#5d4037',
  '#ef6c00',
  '#546e7a',
];

// The scene's colours come from the element's stylesheet (playground.css), where each is a
// documented custom property `--dvf-canvas-…` with a light and a dark default: setPalette
// assigns them before a frame is drawn (ES bindings are live, so every importer sees them).
export let CANVAS_BACKGROUND = '#eef0f3';
export let BOUNDS_FILL = '#ffffff';
export let GRID_COLOUR = '#e3e6ea';
export let AXIS_COLOUR = '#c3c8cf';
export let LABEL_COLOUR = '#6b7280';
export const LABEL_FONT = '11px system-ui, sans-serif';
/** The robots' numbers on the canvas (render/scene.js's drawNumbers). */
export const NUMBER_FONT = '600 11px system-ui, sans-serif';
/**
 * Robots are numbered on the canvas once a safe disc is at least this wide on screen (CSS px:
 * the numbers, about 7 px a digit, then fit between robots whose discs do not overlap) and at
 * most NUMBERS_MAX robots are on screen.
 */
export const NUMBERS_MIN_DISC_PX = 24;
export const NUMBERS_MAX = 150;
export let OBSTACLE_FILL = '#4b5563';
export let INFLUENCE_STROKE = '#9ca3af';
export let INFLUENCE_FILL = 'rgba(156, 163, 175, 0.14)';
export let FIELD_COLOUR = '#94a3b8';
export let CURVE_COLOUR = '#7c3aed';
export const VIRTUAL_OBSTACLE_COLOUR = '#dc2626';
export const SENSE_COLOUR = 'rgba(37, 99, 235, 0.35)';
/** The ring of a robot whose command is at its limit, v_max or ω_max. */
export const SATURATED_COLOUR = '#d97706';
export let HANDLE_FILL = '#ffffff';
export let HANDLE_STROKE = '#111827';
export let SELECTION_COLOUR = '#2563eb';
/** The faint halo of the inspected robot. */
export const FOCUS_HALO = 'rgba(37, 99, 235, 0.12)';
/** The outline of a robot's body. */
export let BODY_OUTLINE = '#1f2937';
/** The fill under a goal's dashed outline. */
export let GOAL_FILL = 'rgba(255, 255, 255, 0.7)';

/**
 * The custom properties of the scene's colours (playground.css), by the name setPalette
 * takes them under. The plots' text, axes and pair line are here too (panels/plots.js).
 */
export const PALETTE_PROPERTIES = {
  canvasBackground: '--dvf-canvas-background',
  boundsFill: '--dvf-canvas-bounds',
  grid: '--dvf-canvas-grid',
  axis: '--dvf-canvas-axis',
  label: '--dvf-canvas-label',
  obstacle: '--dvf-canvas-obstacle',
  influenceStroke: '--dvf-canvas-influence',
  influenceFill: '--dvf-canvas-influence-fill',
  field: '--dvf-canvas-field',
  curve: '--dvf-canvas-curve',
  handleFill: '--dvf-canvas-handle',
  outline: '--dvf-canvas-outline',
  selection: '--dvf-accent',
  goalFill: '--dvf-canvas-goal-fill',
  plotText: '--dvf-plot-text',
  plotAxis: '--dvf-plot-axis',
  plotPair: '--dvf-plot-pair',
};

/**
 * The palette of the element whose shadow-root part `node` is: each of PALETTE_PROPERTIES
 * read from its computed style (the stylesheet resolves each to the page's value or the
 * theme's default).
 * @param {Element} node
 * @returns {Record<keyof typeof PALETTE_PROPERTIES, string>}
 */
export function readPalette(node) {
  const style = getComputedStyle(node);
  /** @type {any} */
  const p = {};
  for (const [key, prop] of Object.entries(PALETTE_PROPERTIES)) {
    p[key] = style.getPropertyValue(prop.replace('--dvf-', '--pg-')).trim();
  }
  return p;
}

/** Makes palette `p` (readPalette) the colours the painters draw with. */
export function setPalette(p) {
  CANVAS_BACKGROUND = p.canvasBackground || CANVAS_BACKGROUND;
  BOUNDS_FILL = p.boundsFill || BOUNDS_FILL;
  GRID_COLOUR = p.grid || GRID_COLOUR;
  AXIS_COLOUR = p.axis || AXIS_COLOUR;
  LABEL_COLOUR = p.label || LABEL_COLOUR;
  OBSTACLE_FILL = p.obstacle || OBSTACLE_FILL;
  INFLUENCE_STROKE = p.influenceStroke || INFLUENCE_STROKE;
  INFLUENCE_FILL = p.influenceFill || INFLUENCE_FILL;
  FIELD_COLOUR = p.field || FIELD_COLOUR;
  CURVE_COLOUR = p.curve || CURVE_COLOUR;
  HANDLE_FILL = p.handleFill || HANDLE_FILL;
  HANDLE_STROKE = p.outline || HANDLE_STROKE;
  BODY_OUTLINE = p.outline || BODY_OUTLINE;
  SELECTION_COLOUR = p.selection || SELECTION_COLOUR;
  GOAL_FILL = p.goalFill || GOAL_FILL;
}

/** Robot glyph: length nose to tail and width at the tail. */
export const ROBOT_LENGTH_PX = 18;
export const ROBOT_WIDTH_PX = 12;
/** Start and goal glyphs are smaller than the moving robot. */
export const MARKER_SCALE = 0.85;
/** Heading handles sit this far from the body's centre, radius HANDLE_RADIUS_PX. */
export const HANDLE_DISTANCE_PX = 30;
export const HANDLE_RADIUS_PX = 5;
/** Field arrows: one per FIELD_SPACING_PX, at most FIELD_ARROW_PX long. */
export const FIELD_SPACING_PX = 34;
export const FIELD_ARROW_PX = 22;
export const TRAIL_WIDTH_PX = 2.5;
export const PREDICTED_WIDTH_PX = 1.75;
export const PREDICTED_ALPHA = 0.55;
export const PREDICTED_DASH_PX = [5, 4];
export const START_ALPHA = 0.45;
export const GOAL_DASH_PX = [3, 2];
export const INFLUENCE_DASH_PX = [6, 4];
export const SAFE_DASH_PX = [2, 3];
export const VIRTUAL_OBSTACLE_DASH_PX = [4, 3];

/**
 * Above this many robots, predicted paths are hairlines, one device pixel wide: without a GPU
 * a wider stroke is outlined and filled as a polygon, a hairline takes the rasteriser's fast
 * path (tests/e2e/bench-browser.mjs holds the frames to their budget).
 */
export const THIN_PREDICTED_ABOVE = 20;
/**
 * Above this many robots the scene is drawn as a crowd (render/crowd.js): goals and bodies
 * stamped as sprites, glyphs shrunk with the zoom, start markers and dashes left out, and the
 * sensing circle and virtual obstacle of the inspected robot only.
 */
export const CROWD_STYLE_ABOVE = 100;

/** One device pixel in CSS pixels at `dpr`: the width of a hairline (see THIN_PREDICTED_ABOVE). */
export function hairline(dpr) {
  return 1 / (dpr || 1);
}

/** Colour of robot `i`. */
export function robotColour(i) {
  return ROBOT_COLOURS[i % ROBOT_COLOURS.length];
}
