// A canvas drawn in CSS pixels at the screen's pixel density.

/**
 * Sizes the canvas' backing store to its CSS box times `dpr` (the screen's devicePixelRatio
 * unless given; `size` [width, height] stands for the box of a canvas not on the page) and
 * returns the context with CSS pixels as drawing units, plus the box size.
 * @param {HTMLCanvasElement} canvas
 * @param {number} [dpr]
 * @param {[number, number]} [size]
 */
export function fitCanvas(
  canvas,
  dpr = window.devicePixelRatio || 1,
  size = [canvas.clientWidth, canvas.clientHeight],
) {
  const width = Math.max(1, size[0]);
  const height = Math.max(1, size[1]);
  const bw = Math.max(1, Math.round(width * dpr));
  const bh = Math.max(1, Math.round(height * dpr));
  if (canvas.width !== bw) canvas.width = bw;
  if (canvas.height !== bh) canvas.height = bh;
  const ctx = canvas.getContext('2d');
  ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
  return { ctx, width, height };
}

/** A canvas of `size`×`size` CSS px at the screen's density, drawn once by `draw(ctx, cx, cy)`. */
export function drawSmallCanvas(canvas, size, draw) {
  canvas.style.width = `${size}px`;
  canvas.style.height = `${size}px`;
  const dpr = window.devicePixelRatio || 1;
  canvas.width = Math.round(size * dpr);
  canvas.height = Math.round(size * dpr);
  const ctx = canvas.getContext('2d');
  ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
  draw(ctx, size / 2, size / 2);
}
