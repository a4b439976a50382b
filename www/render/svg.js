// The scene as SVG, for papers: the same painters that draw the canvas (render/scene.js) draw
// into SvgContext, which stands in for a CanvasRenderingContext2D and keeps each fill, stroke
// and text as one SVG element, so the vector picture is the canvas's mark for mark (trails,
// predicted paths, obstacles, robots, the grid and its labels in metres). Only what the
// painters call is implemented: paths of lines and whole circles, rectangles, text, dashes,
// alpha; pixels (a crowd's sprites, the trail layer) are drawn as paths instead (scene.js).
// The npm package svgcanvas does this for the whole 2D API; the element's modules are served
// as they are, without a bundler to bring it in, and the painters need only these calls.

/** Digits kept of a coordinate (CSS px): a hundredth of a pixel. */
const round = (v) => Math.round(v * 100) / 100;

/** Text for SVG: the scenario's name is free text. */
export function escapeXml(s) {
  return String(s).replace(
    /[&<>"']/g,
    (ch) => ({ '&': '&amp;', '<': '&lt;', '>': '&gt;', '"': '&quot;', "'": '&apos;' })[ch] ?? ch,
  );
}

const ANCHOR = { left: 'start', start: 'start', center: 'middle', right: 'end', end: 'end' };
const BASELINE = {
  top: 'text-before-edge',
  hanging: 'hanging',
  middle: 'central',
  alphabetic: 'alphabetic',
  ideographic: 'ideographic',
  bottom: 'text-after-edge',
};

/**
 * A CanvasRenderingContext2D stand-in that writes SVG (see the top). `toString()` gives the
 * document, `width × height` CSS px.
 */
export class SvgContext {
  constructor(width, height) {
    this.width = width;
    this.height = height;
    /** @type {string[]} */
    this.parts = [];
    /** The current path's data. */
    this.d = '';
    this.fillStyle = '#000';
    this.strokeStyle = '#000';
    this.lineWidth = 1;
    this.globalAlpha = 1;
    this.lineJoin = 'miter';
    this.lineCap = 'butt';
    this.font = '10px sans-serif';
    this.textAlign = 'start';
    this.textBaseline = 'alphabetic';
    /** @type {number[]} */
    this.dash = [];
    /** @type {object[]} */
    this.stack = [];
    // What the painters read of a canvas context.
    this.canvas = { width, height };
  }

  save() {
    const { fillStyle, strokeStyle, lineWidth, globalAlpha, lineJoin, lineCap, font, textAlign, textBaseline, dash } =
      this;
    this.stack.push({
      fillStyle,
      strokeStyle,
      lineWidth,
      globalAlpha,
      lineJoin,
      lineCap,
      font,
      textAlign,
      textBaseline,
      dash,
    });
  }

  restore() {
    Object.assign(this, this.stack.pop() ?? {});
  }

  setLineDash(dash) {
    this.dash = [...dash];
  }

  getLineDash() {
    return [...this.dash];
  }

  // The painters set an identity or a device-pixel transform; the SVG is in CSS px.
  setTransform() {}

  beginPath() {
    this.d = '';
  }

  moveTo(x, y) {
    this.d += `M${round(x)} ${round(y)}`;
  }

  lineTo(x, y) {
    this.d += `L${round(x)} ${round(y)}`;
  }

  closePath() {
    this.d += 'Z';
  }

  /** Whole circles only (all the painters draw): two half arcs. */
  arc(x, y, r, start = 0, end = 2 * Math.PI) {
    const rr = round(Math.abs(r));
    if (Math.abs(end - start) < 2 * Math.PI - 1e-9) {
      const x1 = x + r * Math.cos(start);
      const y1 = y + r * Math.sin(start);
      const x2 = x + r * Math.cos(end);
      const y2 = y + r * Math.sin(end);
      const large = Math.abs(end - start) > Math.PI ? 1 : 0;
      this.d += `${this.d ? 'L' : 'M'}${round(x1)} ${round(y1)}A${rr} ${rr} 0 ${large} 1 ${round(x2)} ${round(y2)}`;
      return;
    }
    this.d += `M${round(x + r)} ${round(y)}A${rr} ${rr} 0 1 1 ${round(x - r)} ${round(y)}A${rr} ${rr} 0 1 1 ${round(x + r)} ${round(y)}`;
  }

  #alpha(name) {
    return this.globalAlpha < 1 ? ` ${name}-opacity="${round(this.globalAlpha)}"` : '';
  }

  #strokeAttributes() {
    const dash = this.dash.length ? ` stroke-dasharray="${this.dash.join(' ')}"` : '';
    const join = this.lineJoin !== 'miter' ? ` stroke-linejoin="${this.lineJoin}"` : '';
    const cap = this.lineCap !== 'butt' ? ` stroke-linecap="${this.lineCap}"` : '';
    return `stroke="${escapeXml(this.strokeStyle)}" stroke-width="${round(this.lineWidth)}"${dash}${join}${cap}${this.#alpha('stroke')}`;
  }

  fill() {
    if (this.d) this.parts.push(`<path d="${this.d}" fill="${escapeXml(this.fillStyle)}"${this.#alpha('fill')}/>`);
  }

  stroke() {
    if (this.d) this.parts.push(`<path d="${this.d}" fill="none" ${this.#strokeAttributes()}/>`);
  }

  fillRect(x, y, w, h) {
    this.parts.push(
      `<rect x="${round(x)}" y="${round(y)}" width="${round(w)}" height="${round(h)}" fill="${escapeXml(this.fillStyle)}"${this.#alpha('fill')}/>`,
    );
  }

  clearRect() {}

  #text(text, x, y, paint) {
    const anchor = ANCHOR[this.textAlign] ?? 'start';
    const baseline = BASELINE[this.textBaseline] ?? 'alphabetic';
    this.parts.push(
      `<text x="${round(x)}" y="${round(y)}" style="font: ${escapeXml(this.font)}" text-anchor="${anchor}" dominant-baseline="${baseline}" ${paint}>${escapeXml(text)}</text>`,
    );
  }

  fillText(text, x, y) {
    this.#text(text, x, y, `fill="${escapeXml(this.fillStyle)}"${this.#alpha('fill')}`);
  }

  strokeText(text, x, y) {
    this.#text(text, x, y, `fill="none" ${this.#strokeAttributes()}`);
  }

  /** A rough width (the stamp sizes its box with it): 0.55 em a character. */
  measureText(text) {
    const px = Number(/(\d+(?:\.\d+)?)px/.exec(this.font)?.[1] ?? 10);
    return { width: String(text).length * px * 0.55 };
  }

  // Pixels have no place in the vector picture.
  drawImage() {}

  toString() {
    const w = round(this.width);
    const h = round(this.height);
    return `<svg xmlns="http://www.w3.org/2000/svg" width="${w}" height="${h}" viewBox="0 0 ${w} ${h}">\n${this.parts.join('\n')}\n</svg>\n`;
  }
}
