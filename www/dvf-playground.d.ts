// Types of <dvf-playground> (dvf-playground.js) and of the JSON it speaks: the scenario format
// (src/scenario.rs, src/params.rs, src/obstacle.rs) and the report of a run (src/sim/report.rs,
// what `dvf simulate` prints and `Run.report()` returns). Lengths in metres, angles in
// radians, times in seconds.

/** A pose `[x, y, θ]`: position (m) and heading (rad, counter-clockwise from +x). */
export type Pose = [x: number, y: number, theta: number];

/** How robots avoid each other (`params.avoidance`). */
export type Avoidance =
  /** As the paper writes it: inside the avoidance range a robot always circles the virtual obstacle. */
  | 'paper'
  /** The paper's field with an exit: a robot whose goal field leads away from the virtual obstacle follows it. */
  | 'exit';

/** The method's parameters; a missing key takes its default. */
export interface Params {
  /** `k_v > 0`: gain of the forward speed on the field (1/s). Default 1. */
  k_v: number;
  /** `k_ω > 0`: gain of the attitude feedback `−k_ω θ̃` (1/s). Default 1. */
  k_omega: number;
  /** `k_a > 0`: gain of the alignment term (1/s). Default 10. */
  k_a: number;
  /** `ε > 0`: width of the transition band of `ς` (m). Default 1. */
  transition_width: number;
  /** `v_c > 0`: the speed of robots circling a virtual obstacle (m/s). Default 2. */
  avoid_speed: number;
  /** `R_c`: radius of the avoidance ring about a virtual obstacle (m). Default 3. */
  avoid_radius: number;
  /** `r_ij`: a robot's safe radius; closer than `2·r_ij` is a collision (m). Default 1. */
  safe_radius: number;
  /** `R_s`: sensing radius (m). Default 20. */
  sense_radius: number;
  /** `|v| ≤ v_max` when set (m/s); null: no saturation (the default). */
  v_max: number | null;
  /** `|ω| ≤ ω_max` when set (rad/s); null: no saturation (the default). */
  omega_max: number | null;
  /** A robot has converged when its position error is at most this (m). Default 0.05. */
  tol_position: number;
  /** … and its heading error at most this (rad). Default 0.02. */
  tol_heading: number;
  /** Field magnitude below which the alignment term fades out (m/s). Default 1e-6. */
  align_fade: number;
  /** Default `exit`. */
  avoidance: Avoidance;
  /** `α`: rate of the safety barrier (1/s), `α·dt ≤ 1/2`; null turns it off. Default 5. */
  barrier_rate: number | null;
}

/** One robot: where it starts and the pose it must reach. */
export interface RobotSpec {
  /** `[x, y, θ]` at time 0. */
  start: Pose;
  /** `[x_d, y_d, θ_d]`. */
  goal: Pose;
}

/** A circular obstacle. */
export interface Obstacle {
  /** Centre `[x, y]`. */
  center: [x: number, y: number];
  /** Radius `r_o > 0` of the disc the robots must stay out of. */
  radius: number;
  /** Radius `R_o > r_o` of the influence ring. */
  influence: number;
}

/**
 * A scenario as the playground returns it (`scenario()`, the `change` event's page, the
 * exported JSON): every default filled in and the bounds resolved.
 */
export interface Scenario {
  /** Free text, shown to people, never interpreted (default "untitled"). */
  name: string;
  /** `[xmin, ymin, xmax, ymax]`: the area drawn (default: the box around every start, goal and ring, with a margin). */
  bounds: [xmin: number, ymin: number, xmax: number, ymax: number];
  /** Simulated seconds (default 40). */
  duration: number;
  /** Step size (s, default 0.01). */
  dt: number;
  params: Params;
  /** Robots run independently (they neither sense nor avoid each other); omitted when false. */
  independent?: boolean;
  /**
   * The planner that drives the robots: a name (`"dvf-paper"`) or an object with its name and
   * gains (`{"name": "avf", "lambda": 2}`); omitted for `dvf` with its defaults.
   */
  planner?: string | { name: string; [gain: string]: unknown };
  /** At least one robot, at most 10,000. */
  robots: RobotSpec[];
  obstacles: Obstacle[];
}

/** A scenario as `load()` and the scenario files accept it: only `robots` is required. */
export type ScenarioInput = Partial<Omit<Scenario, 'params' | 'robots'>> & {
  params?: Partial<Params>;
  robots: RobotSpec[];
};

/** Per-robot outcome in a {@link Report}. */
export interface RobotReport {
  /** `[x, y, θ]` at the end. */
  final: Pose;
  /** Distance to the goal position at the end (m). */
  position_error: number;
  /** `|wrap(θ − θ_d)|` at the end (rad). */
  heading_error: number;
  /** The time after which the robot stayed within the tolerances to the end; null if it ended outside. */
  converged_at: number | null;
  /** How its turn rate moved, step by step. */
  smoothness: SmoothnessTally;
}

/**
 * One robot's turn-rate history: a reversal is a turn (`|ω| > 1 rad/s`) opposite to its previous
 * turn; "settled" counts from the moment it first reached its goal position.
 */
export interface SmoothnessTally {
  /** Reversals over the run. */
  reversals: number;
  /** Reversals since it first reached its goal position. */
  settled_reversals: number;
  /** Steps since it first reached its goal position. */
  settled_steps: number;
  /** Largest `|ω_k − ω_{k−1}|` over the run (rad/s). */
  max_omega_step: number;
  /** Largest `|ω_k − ω_{k−1}|` since it first reached its goal position (rad/s). */
  settled_max_omega_step: number;
}

/** The smoothness of all robots' commands over a run. */
export interface Smoothness {
  /** Reversals per simulated second over all robots and the whole run. */
  reversals_per_s: number;
  /** Reversals per simulated second after the robots reached their goal positions. */
  settled_reversals_per_s: number;
  /** Robots that reverse their turn more than once a second after reaching their goal position. */
  chattering_robots: number;
  /** Largest `|Δω|` of one step over all robots and the whole run (rad/s). */
  max_omega_step: number;
  /** Largest `|Δω|` of one step after a robot reached its goal position (rad/s). */
  settled_max_omega_step: number;
}

/** The outcome of a run (what `dvf simulate` prints). */
export interface Report {
  name: string;
  /** Simulated time at the end (s). */
  time: number;
  /** Steps taken. */
  steps: number;
  robots: RobotReport[];
  /** Smallest distance between two robots at any sampled time; null for one robot or independent runs. */
  min_pair_distance: number | null;
  /** Smallest distance from a robot to the surface of an obstacle it senses; null when none came that close. */
  min_obstacle_clearance: number | null;
  /** Events: each time two robots come closer than `2·safe_radius`, and each time a robot enters an obstacle disc. */
  violations: number;
  /** How smoothly the robots turned. */
  smoothness: Smoothness;
}

/** What a `change` event's `detail.kind` says happened. */
export type ChangeKind =
  | 'robot'
  | 'robot-heading'
  | 'goal'
  | 'goal-heading'
  | 'obstacle'
  | 'obstacle-radius'
  | 'obstacle-influence'
  | 'add-robot'
  | 'add-obstacle'
  | 'delete'
  | 'params'
  | 'preset'
  | 'planner'
  | 'import'
  | 'undo'
  | 'redo';

/** The field overlay: arrows of the inspected robot's field, integral curves of its goal field, or none. */
export type FieldMode = 'arrows' | 'curves' | 'none';

/** The element's attributes (all optional; see docs/book/src/embedding.md). */
export interface DvfPlaygroundAttributes {
  /** A preset name (default: the crate's default preset); `crowd-N` included. */
  preset?: string;
  /** URL of a scenario JSON file; takes precedence over `preset`. */
  src?: string;
  /**
   * The planner that drives the robots (`dvf`, `dvf-paper`, …: the scenario's `planner`, with
   * its default gains), set on the scene that `preset` or `src` loads and when it changes.
   */
  planner?: string;
  /**
   * A second planner (`orca`, `avf`, …): the element opens in compare mode against it, its run
   * drawn over the scene and both runs' metrics in one table (those of `dvf compare`); removed
   * or empty: no comparison. An unknown name shows the core's message, naming `compare`.
   */
  compare?: string;
  /** Present: the full toolbar and side panels. */
  controls?: boolean;
  /** Present: drags and keys edit the scene without the full controls. */
  editable?: boolean;
  /** Present: a figure, not an editor: no drag, no keys, the toolbar's play, pause and reset only. */
  readonly?: boolean;
  /** Present: start playing once loaded; `visible`: play while on screen, pause when scrolled out. */
  autoplay?: boolean | 'visible';
  /** Present: start over from t = 0 at the end of the run (t = duration, or every robot at its goal). */
  loop?: boolean;
  /**
   * Show the state at this time (s) on load and when it changes, simulated from t = 0 in slices
   * like `seekTo` (a long seek shows its progress and never blocks the page).
   */
  time?: number;
  /** `lazy`: load the scene only once the element comes near the viewport. */
  loading?: 'lazy' | 'eager';
  /** URL of `dvf_bg.wasm` (resolved against the page), read by the first element that connects. */
  wasm?: string;
  /** The field overlay (default `arrows`). */
  field?: FieldMode;
  /** θ(0) of the integral curves, in radians (default π/2). */
  theta0?: number;
  /** Present: draw the sensing circles `R_s`. */
  sensing?: boolean;
  /** `light` or `dark` forces a theme; absent: the system's (`prefers-color-scheme`). */
  theme?: 'light' | 'dark';
}

/** What a frame reads of the live simulation: counters, and arrays as views into wasm memory. */
export interface LiveFrame {
  /** Simulated time now (s). */
  readonly time: number;
  /** The scenario's duration (s). */
  readonly duration: number;
  /** Samples per robot in the trail rings. */
  readonly trailCapacity: number;
  /** The next ring slot written, shared by every robot. */
  readonly trailHead: number;
  /** Trail samples written since the last reset (sample `g` is in slot `g % trailCapacity`). */
  readonly recorded: number;
  /** Slots of `trailTimes` and `trailMinPair` written. */
  readonly historyLength: number;
  /** Samples per robot of the prediction (0 without one). */
  readonly predictedSamples: number;
  /** `[robots · 3]`: x, y, θ now. */
  readonly poses: Float64Array;
  /** `[robots · 6]`: v, ω, the obstacle keep, the robot keep, the virtual obstacle's x, y (NaN: none). */
  readonly status: Float64Array;
  /** `[robots · trailCapacity · 3]`: one ring of past poses per robot. */
  readonly trails: Float64Array;
  /** `[robots]`: samples each robot's ring holds, the oldest at `(trailHead − len + cap) % cap`. */
  readonly trailLens: Uint32Array;
  /** `[trailCapacity]`: the time of each ring slot (s). */
  readonly trailTimes: Float64Array;
  /** `[trailCapacity]`: the smallest distance between two robots at each slot (m; NaN: none). */
  readonly trailMinPair: Float64Array;
  /** `[robots · predictedSamples · 3]`: the predicted poses from now on, sample 0 now. */
  readonly predicted: Float64Array;
  /** `[predictedSamples]`: the time of each predicted sample (s). */
  readonly predictedTimes: Float64Array;
  /** `[predictedSamples]`: the predicted smallest distance between two robots (m; NaN: none). */
  readonly predictedMinPair: Float64Array;
}

/** The camera: world centre (m) and scale (CSS px per m). */
export interface CameraState {
  cx: number;
  cy: number;
  scale: number;
}

/** The element's frame statistics (diagnostics for the tests and benchmarks). */
export interface FrameStats {
  /** Frames drawn. */
  frames: number;
  /** When the first frame was drawn (ms since the page's time origin). */
  firstFrameMs: number | undefined;
  /** Wall time of the last edit with its prediction (ms). */
  lastEditMs: number;
  /** Work of the last frame and of the slowest one (ms). */
  frameWorkMs: number;
  maxFrameWorkMs: number;
  /** The work of the last frames (ms), a ring written at `workCount % work.length`. */
  work: Float64Array;
  workCount: number;
  /** Set: a frame's work includes the rasterisation of its drawing. */
  rasterInWork: boolean;
}

/** `<dvf-playground>`: a live DVF simulation with its controls. */
export declare class DvfPlayground extends HTMLElement {
  /**
   * Loads a scenario (object or JSON text) as a new document: t = 0, view fitted, undo cleared.
   * @throws Error naming the offending field; the scene is kept then.
   */
  load(scenario: ScenarioInput | string): void;
  /** Loads a preset by name (`crowd-N` included); on a bad name shows the message, keeps the scene and returns false. */
  loadPreset(name: string): boolean;
  /** The current scenario (edits included) as a plain object; null before the first scene. */
  scenario(): Scenario | null;
  /** The preset shown, or null once the scene has been edited or imported. */
  presetName(): string | null;
  /** How many robots the scene has (0 before the first scene), without the copy `scenario()` makes. */
  readonly robotCount: number;
  /** Offers the scenario as a JSON file; resolves once offered. */
  exportJson(): Promise<void>;
  /** Plays the clock (from t = 0 again after the end). */
  play(): void;
  pause(): void;
  /** Back to t = 0 at the scenario's starts, trails cleared. */
  reset(): void;
  /**
   * Advances `n` steps of dt and pauses; returns the steps taken.
   * @throws Error for an `n` that is not a whole number from 0 to 10⁶.
   */
  step(n?: number): number;
  /** Page coordinates (CSS px, like `pageX`/`pageY`) of world point (x, y) in metres. */
  worldToScreen(x: number, y: number): { x: number; y: number };
  /**
   * Shows the state at time `t` (s, clamped to the run), simulated from t = 0; paused.
   * Returns the time reached (a whole number of steps). Synchronous: it blocks the page while
   * it steps (about a minute to t = 300 s for 10,000 robots); `seekTo` does not.
   * @throws Error for a `t` that is not a number.
   */
  seek(t: number): number;
  /**
   * The state at time `t` as `seek` gives it (the same steps from t = 0), stepped in slices
   * between frames with the progress box and its Cancel: the page stays responsive. Resolves to
   * the time where the seek ends: `t`'s whole step, or where Cancel, Escape, `play()`,
   * `step()`, `seek()` or another scene stopped it.
   * @throws Error (a rejected promise) for a `t` that is not a number.
   */
  seekTo(t: number): Promise<number>;
  /** The simulated time now (s); 0 before the first scene. */
  readonly time: number;
  /** Whether the clock runs. */
  readonly playing: boolean;
  /**
   * Shows `text` (as text, never HTML) over the canvas until the user acts; an empty text hides
   * it. `info`: a notice rather than an error; `actions`: buttons beside it, `[label, run]`.
   */
  showMessage(text: string, options?: { info?: boolean; actions?: [string, () => void][] }): void;
  /** What the view shows (field overlay, θ(0), sensing, inspected robot, time, box in view). */
  viewState(): ViewState | null;
  /** Shows a view (any of its fields; invalid ones are left as they are). */
  setViewState(state: Partial<ViewState>): void;
  /** Resolves once the first scene is shown at its `time` (that seek ended), or its failure message (then `scenario()` is null). */
  readonly loaded: Promise<void>;
  /**
   * Where every element of the page loads the wasm module from: a URL or the module's bytes,
   * set before the first element connects. Undefined: `pkg/dvf_bg.wasm` beside the module.
   */
  static wasmUrl: string | URL | BufferSource | undefined;

  // Diagnostics for the end-to-end tests and benchmarks: not a stable API.
  /** The wasm `Playground` (read only). */
  readonly pg: import('./pkg/dvf.js').Playground | null;
  /** What a frame reads, as views into wasm memory; null before the first scene. */
  readonly cache: LiveFrame | null;
  /** The trail rings (`cache.trails`). */
  trailsView(): Float64Array | null;
  /** The world↔screen maps of the canvas now. */
  view(): {
    scale: number;
    width: number;
    height: number;
    sx(x: number): number;
    sy(y: number): number;
    wx(px: number): number;
    wy(py: number): number;
  };
  readonly camera: CameraState | null;
  readonly stats: FrameStats | null;
  /** Mean wall time of one step (ms). */
  readonly stepMs: number | null;
  readonly fieldMode: FieldMode | null;
  /** The inspected robot. */
  focusRobot: number | null;
  /** The two plots' geometry as last drawn: the time axis (CSS px), the "now" line, the ticks. */
  readonly plotGeometry: PlotGeometry[] | null;

  addEventListener<K extends keyof DvfPlaygroundEventMap>(
    type: K,
    listener: (this: DvfPlayground, event: DvfPlaygroundEventMap[K]) => unknown,
    options?: boolean | AddEventListenerOptions,
  ): void;
  addEventListener(
    type: string,
    listener: EventListenerOrEventListenerObject,
    options?: boolean | AddEventListenerOptions,
  ): void;
}

/** The element's events. */
export interface DvfPlaygroundEventMap extends HTMLElementEventMap {
  /** After each edit. */
  change: CustomEvent<{ kind: ChangeKind }>;
  /** After the clock moved (a playing frame that stepped, `step()`, `seek()`, the scrubber). */
  tick: CustomEvent<{ time: number }>;
  /** The run reached its end: t = duration, or every robot at its goal (the clock stops). */
  finished: CustomEvent<{ time: number }>;
  /** After the view changed (display, camera, inspected robot, the clock at rest). */
  viewchange: CustomEvent;
}

declare global {
  interface HTMLElementTagNameMap {
    'dvf-playground': DvfPlayground;
  }
}

/** One plot's geometry (panels/plots.js), in the plots canvas's CSS px. */
export interface PlotGeometry {
  x0: number;
  x1: number;
  nowX: number;
  timeTicks: number[];
  valueTicks: number[];
  /** The left axis's labels, one per value tick. */
  valueLabels: string[];
  /** The right axis's labels (the heading error, rad), empty for a plot without one. */
  rightLabels: string[];
}

/** What a view shows, for a link: see `DvfPlayground.viewState`. */
export interface ViewState {
  field: FieldMode;
  /** θ(0) of the integral curves (rad). */
  theta0: number;
  sensing: boolean;
  /** The inspected robot, from 0. */
  robot: number;
  /** The time (s). */
  time: number;
  /** The world box in view ([xmin, ymin, xmax, ymax], m) once panned or zoomed, else null. */
  box: [number, number, number, number] | null;
  /** The planner the scene is compared with (drawn over it, both in the results), or null. */
  compare: string | null;
}
