// The toolbar of a playground: preset menu (with the crowd's N box), play, step, reset and
// speed, undo and redo, add and delete, the field overlay with θ(0) (rad), the sensing circles and
// fit, and the exports and import. Without the `controls` attribute the stylesheet hides all
// but play, step, reset and the field menu.

import { csvSize, downloadCsv, formatBytes, MAX_CSV_BYTES, readScenarioFile, trajectoriesCsv } from '../io.js';
import { addObstacleInView, addRobotInView, deleteSelection } from '../playground/actions.js';
import { exportPng, exportSvg } from '../playground/record.js';
import { DEFAULT_SPEED, SPEEDS } from '../playground/loop.js';
import { messageOf } from '../playground/message.js';
import { el } from './dom.js';
import { boxText, exact, numberBox, parseNumber } from './format.js';

/** A crowd loaded from the menu has this many robots unless the N box says otherwise. */
const DEFAULT_CROWD = 1000;
/** Crowds are the presets `crowd-N`. */
const CROWD_PREFIX = 'crowd-';
/** The menu's entry for a crowd. */
const CROWD_OPTION = 'crowd';

/**
 * A preset's name in the menu: its summary up to the first colon ("Example 4", "Example 3,
 * scenario 2") and the rest of the slug after the example's number ("obstacle formation").
 * @param {{name: string, summary: string}} p
 */
export function presetLabel({ name, summary }) {
  const head = summary.split(':')[0].trim();
  // The name less its family (`example3-`, `teach-`, `real-example3-`), which the summary's
  // head says.
  const words = name.replace(/^(?:real-)?(?:[a-z]+\d+-?|teach-)?/, '').replace(/-/g, ' ');
  return words ? `${head}: ${words}` : head;
}

/**
 * What the toolbar uses of the controller: the commands its buttons and menus give, and what
 * it shows.
 * @typedef {Pick<import('../playground/controller.js').Controller, '$' | 'canvas' | 'clock'
 *   | 'exportJson' | 'fit' | 'gestures' | 'help' | 'history' | 'importScenario' | 'limits'
 *   | 'loadPreset' | 'loop' | 'messages' | 'painter' | 'pg' | 'presetName' | 'recorder'
 *   | 'scenario' | 'selection' | 'setDisplay' | 'showMessage' | 'theta0'>
 *   & import('../playground/actions.js').ActionsHost
 *   & import('../playground/record.js').PictureHost} ToolbarHost
 */

export class Toolbar {
  /** @param {ToolbarHost} controller */
  constructor(controller) {
    const c = controller;
    const $ = c.$;
    this.c = c;
    const speed = $('speed');
    for (const s of SPEEDS) {
      const o = el('option', `${s}×`);
      o.value = String(s);
      speed.append(o);
    }
    speed.value = String(DEFAULT_SPEED);
    speed.addEventListener('change', () => {
      c.loop.speed = Number(speed.value);
    });
    $('preset').addEventListener('change', () => {
      if ($('preset').value === CROWD_OPTION) this.loadCrowd();
      else c.loadPreset($('preset').value, { edit: true });
      // The keys act on the new scene at once (the menu would take letters as a search).
      if ($('preset').value !== CROWD_OPTION) c.canvas.focus({ preventScroll: true });
    });
    $('crowd-n').addEventListener('change', () => this.loadCrowd());
    $('play').addEventListener('click', () => c.clock.togglePlay());
    $('step').addEventListener('click', () => c.clock.stepTime());
    $('reset').addEventListener('click', () => c.clock.reset());
    // The scrubber: any time of the run (a seek, frame by frame); the frame keeps it in step
    // with the clock unless it is held.
    const scrubber = $('scrubber');
    this.scrubbing = false;
    scrubber.addEventListener('pointerdown', () => {
      this.scrubbing = true;
    });
    const release = () => {
      this.scrubbing = false;
    };
    scrubber.addEventListener('pointerup', release);
    scrubber.addEventListener('change', release);
    scrubber.addEventListener('input', () => {
      if (c.pg) c.clock.seekTo((Number(scrubber.value) / Number(scrubber.max)) * c.pg.duration);
    });
    $('plots').addEventListener('pointerdown', (e) => {
      const t = c.painter.plots.timeAt(e.offsetX);
      if (t != null) c.clock.seekTo(t);
    });
    $('undo').addEventListener('click', () => c.gestures.undo());
    $('redo').addEventListener('click', () => c.gestures.redo());
    $('add-robot').addEventListener('click', () => addRobotInView(c));
    $('add-obstacle').addEventListener('click', () => addObstacleInView(c));
    $('delete').addEventListener('click', () => deleteSelection(c));
    $('fit').addEventListener('click', () => c.fit());
    $('help').addEventListener('click', () => c.help.toggle());
    // The display menus: a θ(0) that is not a number keeps the one shown, the typed text
    // marked, and says what is wrong with it.
    const theta0 = $('theta0');
    numberBox(theta0, () => c.theta0);
    /** @param {Event} e */
    const display = (e) => {
      const typed = parseNumber(theta0.value);
      const ok = typed.error === undefined && !typed.empty;
      if (ok) {
        if (theta0.getAttribute('aria-invalid') === 'true') c.showMessage('');
        theta0.removeAttribute('aria-invalid');
        delete theta0.dataset.edited;
      } else if (e.target === theta0) {
        theta0.setAttribute('aria-invalid', 'true');
        c.showMessage(`θ(0): ${typed.empty ? 'a value is needed' : typed.error} (an angle in rad)`);
      }
      const angle = ok ? /** @type {number} */ (typed.value) : c.theta0;
      c.setDisplay({ field: $('field').value, theta0: angle, sensing: $('sensing').checked });
    };
    for (const id of ['field', 'theta0', 'sensing']) $(id).addEventListener('change', display);
    $('export-json').addEventListener('click', () => c.exportJson());
    $('export-png').addEventListener('click', () => exportPng(c, Number($('png-scale').value)));
    $('export-svg').addEventListener('click', () => exportSvg(c));
    $('record').addEventListener('click', () => c.recorder.toggle());
    $('export-csv').addEventListener('click', () => this.exportCsv());
    $('import').addEventListener('click', () => $('import-file').click());
    $('import-file').addEventListener('change', async () => {
      const input = $('import-file');
      const file = input.files?.[0];
      input.value = '';
      if (!file) return;
      try {
        await c.importScenario(await readScenarioFile(file));
      } catch (e) {
        c.showMessage(`Could not import ${file.name}: ${messageOf(e)}`);
      }
    });
  }

  /**
   * Writes the CSV of the whole run in slices, its progress over the canvas with a Cancel
   * button; a run whose CSV would be larger than MAX_CSV_BYTES is refused up front with its
   * size, pointing to the command line.
   */
  async exportCsv() {
    const c = this.c;
    const s = c.scenario();
    if (!s) return;
    const { rows, bytes } = csvSize(s);
    if (bytes > MAX_CSV_BYTES) {
      c.showMessage(
        `CSV: the whole run is ${rows.toLocaleString('en')} rows, about ${formatBytes(bytes)}: more than the page writes (${formatBytes(MAX_CSV_BYTES)}). ` +
          'Save the Scenario JSON and run "dvf simulate scenario.json --csv out.csv" (the same format).',
        { actions: [['Scenario JSON', () => c.exportJson()]] },
      );
      return;
    }
    const abort = new AbortController();
    const button = c.$('export-csv');
    button.disabled = true;
    c.showMessage('Writing the CSV: 0 %', { info: true, source: 'csv', actions: [['Cancel', () => abort.abort()]] });
    try {
      const pieces = await trajectoriesCsv(s, {
        signal: abort.signal,
        progress: (f) => {
          c.messages.update('csv', `Writing the CSV: ${Math.floor(f * 100)} %`);
        },
      });
      c.messages.clear('csv');
      if (pieces) downloadCsv(pieces, s);
    } catch (e) {
      c.showMessage(`CSV: ${messageOf(e)}`);
    } finally {
      button.disabled = false;
    }
  }

  /** Fills the preset menu: an "(edited or imported)" entry, the presets, and the crowd. */
  fillMenus(presets, crowdMax) {
    const $ = this.c.$;
    const select = $('preset');
    const custom = el('option', '(edited or imported)');
    custom.value = '';
    custom.disabled = true;
    select.append(custom);
    for (const p of presets) {
      const o = el('option', presetLabel(p));
      o.value = p.name;
      o.title = p.summary;
      select.append(o);
    }
    const crowd = el('option', 'crowd of N robots');
    crowd.value = CROWD_OPTION;
    crowd.title = `N robots (1 to ${crowdMax}) swap antipodally on a circle, keeping their headings`;
    select.append(crowd);
    const crowdN = $('crowd-n');
    crowdN.max = String(crowdMax);
    crowdN.value = String(DEFAULT_CROWD);
  }

  /** Loads a crowd of the N in the N box (as an edit); a bad N is named and changes nothing. */
  loadCrowd() {
    const c = this.c;
    const box = c.$('crowd-n');
    const n = Number(box.value);
    const max = c.limits.crowdMax;
    if (!Number.isInteger(n) || n < 1 || n > max) {
      c.showMessage(`crowd: N must be a whole number from 1 to ${max}, not ${box.value || 'empty'}`);
      this.showPreset(c.presetName());
      return false;
    }
    return c.loadPreset(`${CROWD_PREFIX}${n}`, { edit: true });
  }

  /** The preset menu (and N box) showing preset `name`, or "(edited or imported)" for null. */
  showPreset(name) {
    const $ = this.c.$;
    const shown = name ?? '';
    const crowd = shown.startsWith(CROWD_PREFIX);
    $('preset').value = crowd ? CROWD_OPTION : shown;
    $('crowd-box').hidden = !crowd;
    if (crowd) $('crowd-n').value = shown.slice(CROWD_PREFIX.length);
  }

  /** The field menu, θ(0) and the sensing box showing the controller's display options. */
  showDisplay({ fieldMode, theta0, showSensing }) {
    const $ = this.c.$;
    $('field').value = fieldMode;
    const box = $('theta0');
    if (box.getAttribute('aria-invalid') !== 'true') {
      box.value = box === box.getRootNode().activeElement ? exact(theta0) : boxText(theta0, box);
    }
    $('sensing').checked = showSensing;
  }

  /** The scrubber at time `t` of `duration` (s), unless it is held. */
  showTime(t, duration) {
    if (this.scrubbing) return;
    const scrubber = this.c.$('scrubber');
    scrubber.value = String(Math.round((t / (duration || 1)) * Number(scrubber.max)));
  }

  /** The play button and the undo, redo and delete buttons as the state is now. */
  update() {
    const c = this.c;
    const play = c.$('play');
    play.textContent = c.loop.playing ? 'Pause' : 'Play';
    play.setAttribute('aria-pressed', String(c.loop.playing));
    c.$('undo').disabled = !c.history.canUndo;
    c.$('redo').disabled = !c.history.canRedo;
    c.$('delete').disabled = !c.selection;
    const record = c.$('record');
    record.textContent = c.recorder.active ? 'Stop' : 'Record';
    record.setAttribute('aria-pressed', String(c.recorder.active));
  }
}
