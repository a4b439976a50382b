// The README's picture, docs/playground.png: the main page at 1280×800, scale 1, on the scene
// of showReadmeScene (Example 4 as the robots pass the obstacle, the field of the robot that
// goes round it), from the RELEASE wasm package. The one script that writes outside
// test-results/.
//
// Run: make picture   (or: node tests/e2e/picture.mjs after make build-wasm)

import { check, checkQuiet, join, ROOT, run, showReadmeScene, waitLoaded } from './lib.mjs';

const VIEWPORT = { width: 1280, height: 800 };
const PICTURE = join(ROOT, 'docs', 'playground.png');

await run(async ({ base, newPage }) => {
  const page = await newPage({ viewport: VIEWPORT, deviceScaleFactor: 1 });
  await page.goto(`${base}/`);
  await waitLoaded(page);
  await showReadmeScene(page);
  await page.screenshot({ path: PICTURE });
  check(true, `wrote ${PICTURE}`);
  checkQuiet(page, 'README picture page');
});
