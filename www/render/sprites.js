// Sprites: crowds drawn by stamping pre-rasterised glyphs into a pixel buffer.
//
// In Chromium without a GPU (the headless test browser, and many laptops' fallback) every
// Canvas 2D path call has a fixed cost, so a crowd's triangles drawn as paths cost in
// proportion to the robots whatever the batching (fillRect is no cheaper). Here each glyph is
// drawn once per colour, heading (HEADINGS steps) and size on a small canvas, read back, and
// copied pixel by pixel into one ImageData per frame, which is put on the scene with a single
// drawImage. tests/e2e/bench-browser.mjs holds the crowd's frame to its budget.

/** Heading steps of the pre-rasterised glyphs (11.25° apart). */
export const HEADINGS = 32;

/** One glyph's pixels: `size × size`, RGBA words and their alpha, centred. */
class Sprite {
  constructor(size, rgba) {
    this.size = size;
    this.rgba = new Uint8Array(rgba);
    this.words = new Uint32Array(this.rgba.buffer);
    this.alpha = new Uint8Array(size * size);
    for (let k = 0; k < size * size; k++) this.alpha[k] = rgba[4 * k + 3];
  }
}

/** A pixel layer for crowds: `begin`, any number of `stamp`s, `end`. */
export class SpriteLayer {
  constructor() {
    this.canvas = document.createElement('canvas');
    this.ctx = this.canvas.getContext('2d');
    this.image = null;
    this.bytes = null;
    this.words = null;
    this.width = 0;
    this.height = 0;
    /** Sprite sets by `kind|size|dpr`: `sets.get(key)[colour * HEADINGS + heading]`. */
    this.sets = new Map();
  }

  /** Starts a frame of `width × height` device pixels, all transparent. */
  begin(width, height) {
    if (width !== this.width || height !== this.height) {
      this.width = width;
      this.height = height;
      this.canvas.width = width;
      this.canvas.height = height;
      this.image = this.ctx.createImageData(width, height);
      this.bytes = this.image.data;
      this.words = new Uint32Array(this.bytes.buffer);
    } else {
      this.words.fill(0);
    }
  }

  /**
   * The sprites of `kind` at `size` device pixels for each of `colours`: `draw(ctx, c, theta,
   * colour)` draws one glyph centred at (c, c) in device pixels on a `size × size` canvas.
   * Made once per kind, size and colour list, then reused.
   */
  sprites(kind, size, colours, draw) {
    const key = `${kind}|${size}`;
    let set = this.sets.get(key);
    if (set) return set;
    if (this.sets.size > 16) this.sets.clear(); // zooming through many sizes
    const c = document.createElement('canvas');
    c.width = size;
    c.height = size;
    const ctx = c.getContext('2d', { willReadFrequently: true });
    set = [];
    for (const colour of colours) {
      for (let h = 0; h < HEADINGS; h++) {
        ctx.clearRect(0, 0, size, size);
        draw(ctx, size / 2, (2 * Math.PI * h) / HEADINGS, colour);
        set.push(new Sprite(size, ctx.getImageData(0, 0, size, size).data));
      }
    }
    this.sets.set(key, set);
    return set;
  }

  /** The sprite of a set for colour index `colour` and heading `theta` (rad, world CCW). */
  static pick(set, colour, theta) {
    const h = Math.round((theta / (2 * Math.PI)) * HEADINGS) % HEADINGS;
    return set[colour * HEADINGS + (h < 0 ? h + HEADINGS : h)];
  }

  /** Copies `sprite` centred at device pixel (x, y), blending its soft edge over what is there. */
  stamp(sprite, x, y) {
    const s = sprite.size;
    const x0 = Math.round(x - s / 2);
    const y0 = Math.round(y - s / 2);
    const w = this.width;
    const h = this.height;
    if (x0 >= w || y0 >= h || x0 + s <= 0 || y0 + s <= 0) return;
    const words = this.words;
    const bytes = this.bytes;
    const sw = sprite.words;
    const sb = sprite.rgba;
    const sa = sprite.alpha;
    for (let sy = Math.max(0, -y0); sy < s && y0 + sy < h; sy++) {
      const row = (y0 + sy) * w + x0;
      const srow = sy * s;
      for (let sx = Math.max(0, -x0); sx < s && x0 + sx < w; sx++) {
        const a = sa[srow + sx];
        if (a === 0) continue;
        const d = row + sx;
        const da = bytes[4 * d + 3];
        if (a === 255 || da === 0) {
          words[d] = sw[srow + sx];
          continue;
        }
        // "Source over" on straight (non-premultiplied) colour.
        const fa = a / 255;
        const fd = (da / 255) * (1 - fa);
        const out = fa + fd;
        const o = 4 * d;
        const so = 4 * (srow + sx);
        bytes[o] = (sb[so] * fa + bytes[o] * fd) / out;
        bytes[o + 1] = (sb[so + 1] * fa + bytes[o + 1] * fd) / out;
        bytes[o + 2] = (sb[so + 2] * fa + bytes[o + 2] * fd) / out;
        bytes[o + 3] = out * 255;
      }
    }
  }

  /** Puts the frame on `ctx` over a `cssWidth × cssHeight` box. */
  end(ctx, cssWidth, cssHeight) {
    this.ctx.putImageData(this.image, 0, 0);
    ctx.drawImage(this.canvas, 0, 0, cssWidth, cssHeight);
  }
}
