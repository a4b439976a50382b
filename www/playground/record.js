// Recording what the canvas shows: a PNG at 1×, 2× or 4× the CSS size (drawn anew at that
// density, not scaled up), an SVG of the same picture as vectors (render/svg.js), and a WebM video through the browser's own MediaRecorder, both with
// the scenario's title and the time stamped in (the page's clock and title are HTML over the
// canvas, not in it).

import { downloadBlob, fileStem } from '../io.js';
import { messageOf } from './message.js';

/** Frames per second of a recording (the canvas is captured when it changes, at most this). */
const RECORD_FPS = 30;
/** A recording hands over its data this often (ms): the progress shown. */
const RECORD_SLICE_MS = 500;
/** The containers tried, best first. */
const WEBM_TYPES = ['video/webm;codecs=vp9', 'video/webm;codecs=vp8', 'video/webm'];

/**
 * What the picture exports use of the controller.
 * @typedef {Pick<import('./controller.js').Controller, 'model' | 'painter' | 'requestDraw' | 'showMessage'>} PictureHost
 */

/**
 * Draws the picture of controller `c` at `scale` times the CSS size and offers it as a PNG.
 * @param {PictureHost} c
 */
export function exportPng(c, scale) {
  const canvas = document.createElement('canvas');
  c.painter.draw({ canvas, dpr: scale });
  canvas.toBlob((blob) => {
    if (blob) downloadBlob(blob, `${fileStem(c.model.name)}-${scale}x.png`);
    else c.showMessage('PNG: the browser could not encode the picture');
  }, 'image/png');
  c.requestDraw();
}

/**
 * Offers the picture of controller `c` as an SVG file (Painter.svg: the canvas as vectors).
 * @param {PictureHost} c
 */
export function exportSvg(c) {
  let text = '';
  try {
    text = c.painter.svg();
  } catch (e) {
    c.showMessage(`SVG: ${messageOf(e)}`);
    return;
  }
  downloadBlob(new Blob([text], { type: 'image/svg+xml' }), `${fileStem(c.model.name)}.svg`);
}

/** A WebM recording of one playground's canvas. */
export class Recorder {
  /**
   * @param {{
   *   canvas: HTMLCanvasElement,
   *   name: () => string,
   *   messages: import('./message-box.js').MessageBox,
   *   shown: () => void,
   *   requestDraw: () => void,
   * }} host the canvas recorded; the scenario's name, for the file; the message box the
   *   progress shows in; what updates the toolbar; what asks for a frame
   */
  constructor(host) {
    this.host = host;
    /** @type {MediaRecorder | null} */
    this.recorder = null;
    /** @type {Blob[]} */
    this.chunks = [];
    this.bytes = 0;
    this.startedMs = 0;
  }

  get active() {
    return this.recorder !== null;
  }

  /** Starts recording, or stops (and offers the file) when recording. */
  toggle() {
    if (this.recorder) this.stop();
    else this.start();
  }

  start() {
    const { canvas, messages, shown, requestDraw } = this.host;
    const type = typeof MediaRecorder === 'undefined' ? null : WEBM_TYPES.find((t) => MediaRecorder.isTypeSupported(t));
    if (!type) {
      messages.show('Record: this browser cannot record a canvas as WebM (MediaRecorder)');
      return;
    }
    try {
      const stream = canvas.captureStream(RECORD_FPS);
      const recorder = new MediaRecorder(stream, { mimeType: type });
      this.chunks = [];
      this.bytes = 0;
      recorder.ondataavailable = (e) => {
        if (e.data.size) {
          this.chunks.push(e.data);
          this.bytes += e.data.size;
        }
        this.progress();
      };
      recorder.onstop = () => this.finish(type);
      recorder.start(RECORD_SLICE_MS);
      this.recorder = recorder;
      this.startedMs = performance.now();
    } catch (e) {
      messages.show(`Record: ${messageOf(e)}`);
      return;
    }
    messages.show('Recording: 0.0 s', { info: true, source: 'record', actions: [['Stop', () => this.stop()]] });
    shown();
    requestDraw();
  }

  stop() {
    if (!this.recorder) return;
    this.recorder.stop();
    this.recorder = null;
    this.host.shown();
  }

  /** The recording's length and size, over the canvas. */
  progress() {
    if (!this.recorder) return;
    const s = (performance.now() - this.startedMs) / 1000;
    this.host.messages.update('record', `Recording: ${s.toFixed(1)} s, ${(this.bytes / 1e6).toFixed(1)} MB`);
  }

  finish(type) {
    const { name, messages, requestDraw } = this.host;
    messages.clear('record');
    const blob = new Blob(this.chunks, { type: type.split(';')[0] });
    this.chunks = [];
    downloadBlob(blob, `${fileStem(name())}.webm`);
    requestDraw();
  }
}
