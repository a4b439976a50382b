// The look of the scene and its legend: colours, line widths, dash patterns, glyph sizes and
// fonts, in one place. Sizes are CSS pixels.

/** One colour per robot, cycled (Tableau 10: distinct, and legible on white). */
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
];
export const CANVAS_BACKGROUND = '#eef0f3';
export const BOUNDS_FILL = '#ffffff';
export const GRID_COLOUR = '#e3e6ea';
export const AXIS_COLOUR = '#c3c8cf';
export const LABEL_COLOUR = '#6b7280';
export const LABEL_FONT = '11px system-ui, sans-serif';
export const OBSTACLE_FILL = '#4b5563';
export const INFLUENCE_STROKE = '#9ca3af';
export const INFLUENCE_FILL = 'rgba(156, 163, 175, 0.14)';
export const FIELD_COLOUR = '#94a3b8';
export const CURVE_COLOUR = '#7c3aed';
export const VIRTUAL_OBSTACLE_COLOUR = '#dc2626';
export const SENSE_COLOUR = 'rgba(37, 99, 235, 0.35)';
export const HANDLE_FILL = '#ffffff';
export const HANDLE_STROKE = '#111827';
export const SELECTION_COLOUR = '#2563eb';
/** The faint halo of the inspected robot. */
export const FOCUS_HALO = 'rgba(37, 99, 235, 0.12)';
/** The outline of a robot's body. */
export const BODY_OUTLINE = '#1f2937';
/** The fill under a goal's dashed outline. */
export const GOAL_FILL = 'rgba(255, 255, 255, 0.7)';

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
 * path (100 robots' paths: 30 ms against 5).
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
