// The HTML of <dvf-playground>'s shadow root: toolbar, canvas with its clock, title, hint, a
// long seek's progress and message (over the canvas, so that a message moves nothing), and the side panels (inspected robot with its plots, parameters, legend).
// Parts are found by their `data-id`; the stylesheet is ../playground.css, found relative to
// this module. Nothing from a scenario is ever put into this HTML.

export const TEMPLATE = `
<link rel="stylesheet" href="${new URL('../playground.css', import.meta.url)}">
<div class="pg" part="root">
  <div class="toolbar" role="toolbar" aria-label="Playground controls">
    <span class="group full scene">
      <label>Preset <select data-id="preset" aria-label="Load a preset of the paper's examples"></select></label>
      <label data-id="crowd-box" hidden>N <input data-id="crowd-n" class="crowd-n" inputmode="numeric" autocomplete="off" aria-label="Robots in the crowd"></label>
      <label title="The planner that drives the robots (the scenario's planner)">Planner <select data-id="planner" aria-label="The planner that drives the robots"></select></label>
      <label title="Run the same scene with a second planner, drawn over this one, both in the results">vs <select data-id="compare" aria-label="Compare with a second planner"></select></label>
    </span>
    <span class="group">
      <button type="button" data-id="play" aria-pressed="false" title="Play / pause (Space)">Play</button>
      <button type="button" data-id="step" title="Advance 0.1 s (S)">Step</button>
      <button type="button" data-id="reset" title="Back to t = 0 at the starts (R)">Reset</button>
      <input type="range" data-id="scrubber" class="scrubber" min="0" max="1000" step="1" value="0" aria-label="Time of the run: drag to go to any time" title="Go to any time of the run">
      <label class="full">Speed <select data-id="speed" aria-label="Playback speed"></select></label>
    </span>
    <span class="group full">
      <button type="button" data-id="undo" title="Undo (Ctrl+Z)">Undo</button>
      <button type="button" data-id="redo" title="Redo (Ctrl+Shift+Z)">Redo</button>
      <button type="button" data-id="add-robot" title="Add a robot at the centre of the view (A)">+ Robot</button>
      <button type="button" data-id="add-obstacle" title="Add an obstacle at the centre of the view (O)">+ Obstacle</button>
      <button type="button" data-id="delete" title="Delete the selected robot or obstacle (Delete)">Delete</button>
    </span>
    <span class="group display">
      <label>Field <select data-id="field" aria-label="Field display">
        <option value="arrows">arrows Γ</option><option value="curves">integral curves</option><option value="none">off</option>
      </select></label>
      <label title="The start attitude θ(0) of the integral curves (rad)">θ(0) <input data-id="theta0" aria-label="θ(0) of the integral curves, radians"> rad</label>
      <label class="check full"><input data-id="sensing" type="checkbox"> R_s</label>
      <button type="button" data-id="fit" class="full" title="Fit the scenario in the view (F)">Fit</button>
      <button type="button" data-id="help" title="The controls and keys (?)" aria-label="Help: the controls and keys">?</button>
    </span>
    <span class="group full">
      <button type="button" data-id="export-json" title="Download the scenario as JSON">Scenario JSON</button>
      <button type="button" data-id="export-png" title="Download the picture as PNG, the title and the time stamped in">PNG</button>
      <select data-id="png-scale" aria-label="PNG size: times the canvas's size"><option value="1">1×</option><option value="2" selected>2×</option><option value="4">4×</option></select>
      <button type="button" data-id="export-svg" title="Download the picture as SVG (vectors: trails, paths, obstacles, robots, axes), for papers">SVG</button>
      <button type="button" data-id="record" aria-pressed="false" title="Record the canvas as a WebM video (again: stop and download)">Record</button>
      <button type="button" data-id="export-csv" title="Download the whole run's trajectories as CSV">CSV</button>
      <button type="button" data-id="import" title="Load a scenario JSON file">Import…</button>
      <input data-id="import-file" type="file" accept=".json,application/json" hidden>
    </span>
  </div>
  <div class="body">
    <div class="stage">
      <canvas data-id="canvas" tabindex="0" role="application"
        aria-label="Playground canvas. Drag robots, goals and obstacles; keys: Space play, S step, R reset, arrows move, Q and E turn, A add robot, O add obstacle, Delete, brackets select, F fit."></canvas>
      <div class="overlay">
        <div class="overlay-row"><div class="clock" data-id="clock"></div><div class="title" data-id="title"></div></div>
        <div class="compare-legend" data-id="compare-legend" hidden></div>
        <button type="button" class="violations full" data-id="violations" hidden></button>
        <div class="hint" data-id="hint"></div>
      </div>
      <div class="help" data-id="help-panel" role="dialog" aria-label="Controls and keys" hidden>
        <button type="button" data-id="help-close" class="help-close" aria-label="Close the help">×</button>
        <h3>Mouse, touch and pen</h3>
        <p>Drag a robot, goal or obstacle to move it; click one to select it. A selected robot or goal has a round handle: drag it to turn the heading. A selected obstacle has two: its disc r_o and its ring R_o. Drag the background to pan; the wheel or two fingers zoom. Robots on top of one another: click again to pick the next. Click a plot, or drag the scrubber, to go to a time.</p>
        <h3>Keys (anywhere in the playground but in a text field)</h3>
        <dl class="help-keys">
          <dt>Space</dt><dd>play / pause</dd><dt>S</dt><dd>advance 0.1 s</dd><dt>R</dt><dd>back to t = 0</dd>
          <dt>[ ]</dt><dd>select the previous / next robot</dd><dt>G</dt><dd>switch between a robot and its goal</dd>
          <dt>arrows</dt><dd>move the selection</dd><dt>Q E</dt><dd>turn it</dd><dt>A O</dt><dd>add a robot / an obstacle</dd>
          <dt>Delete</dt><dd>remove the selection</dd><dt>Ctrl+Z</dt><dd>undo (Ctrl+Shift+Z, Ctrl+Y: redo)</dd>
          <dt>+ −</dt><dd>zoom</dd><dt>F</dt><dd>fit the scenario</dd><dt>Escape</dt><dd>deselect, close this help, stop a seek</dd><dt>?</dt><dd>this help</dd>
        </dl>
      </div>
      <div class="seek" data-id="seek" role="status" hidden><progress data-id="seek-bar" max="1" value="0"></progress><span data-id="seek-text"></span><button type="button" data-id="seek-cancel" title="Stop the seek at the time reached (Escape)">Cancel</button></div>
      <div class="message" data-id="message" role="alert" hidden><span class="message-text" data-id="message-text"></span><span data-id="message-actions"></span><button type="button" data-id="message-close" aria-label="Dismiss the message" title="Dismiss">×</button></div>
    </div>
    <aside class="side full">
      <section>
        <h3>Inspected robot</h3>
        <p class="robot-info" data-id="robot-info"></p>
        <canvas data-id="plots" aria-label="Minimum pair distance and the selected robot's errors over time; click to go to a time"></canvas>
        <ul class="plots-legend" data-id="plots-legend"></ul>
      </section>
      <section>
        <h3>Results <button type="button" data-id="copy-results" class="small" disabled title="Copy the report (the JSON of dvf simulate)">Copy JSON</button><button type="button" data-id="pin" class="small">Pin</button></h3>
        <div class="results compare" data-id="compare-results" hidden></div>
        <div class="results pinned" data-id="pinned" hidden></div>
        <div class="results" data-id="results"></div>
      </section>
      <section class="params-section">
        <h3>By number: <span data-id="selection-title"></span></h3>
        <form data-id="selection" class="params"></form>
      </section>
      <section class="params-section">
        <h3>Parameters</h3>
        <form data-id="params" class="params"></form>
      </section>
      <section>
        <h3>Legend</h3>
        <ul class="legend" data-id="legend"></ul>
        <p class="keys">Drag a robot, goal or obstacle to move it; drag a handle to turn a heading or resize a disc or ring; drag the background to pan, wheel to zoom. Keys on the canvas: Space play, S step, R reset, arrows move, Q/E turn, [ ] select, A/O add, Delete, Ctrl+Z/Ctrl+Shift+Z, +/− zoom, F fit.</p>
      </section>
    </aside>
  </div>
</div>`;
