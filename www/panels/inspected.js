// The "Inspected robot" line of the side panel: the robot's number in its own colour, its
// speed and turn rate now, and what it is avoiding.

import { STATUS, STATUS_STRIDE } from '../playground/wasm-views.js';
import { robotColour } from '../render/theme.js';
import { fixed } from './format.js';

/** Shows robot `i` of `robots` in `box`, from the status array `status` (wasm-views.js). */
export function showInspected(box, i, robots, status) {
  const o = i * STATUS_STRIDE;
  const v = status[o + STATUS.v];
  const omega = status[o + STATUS.omega];
  const nearObstacle = status[o + STATUS.obstacleKeep] < 1;
  const avoiding = !Number.isNaN(status[o + STATUS.virtualX]);
  // The robot's own colour beside its number, so the text and the canvas match.
  box.style.borderLeftColor = robotColour(i);
  box.textContent =
    `Robot ${i + 1} of ${robots}: v = ${fixed(v, 2)} m/s, ω = ${fixed(omega, 2)} rad/s` +
    `${nearObstacle ? ', avoiding an obstacle' : ''}${avoiding ? ', avoiding robots' : ''}.`;
}
