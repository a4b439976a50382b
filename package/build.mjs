// `make package`: the npm package `dvf-playground` from the release build in www/ (which
// `make build-wasm` writes), into target/package/dvf-playground/, and its tarball
// target/package/dvf-playground-VERSION.tgz (`npm pack`). What goes in:
//   - the element's ES modules as www/ holds them (dvf-playground.js and the modules it imports,
//     found relative to each other), its stylesheet and declarations;
//   - pkg/: the wasm module and its low-level bindings (wasm-pack's dvf.js, dvf.d.ts);
//   - dvf-playground.inline.js: the same element in one ES module with the wasm module and the
//     stylesheet inlined (base64 data URLs), for hosts that cannot serve a .wasm file (Vite's
//     library mode, the version pinned in package.json);
//   - loader.js: a classic script that imports the element beside it, for hosts that include
//     classic scripts only (mdBook's additional-js), and mdbook.js, which keeps the figures'
//     theme in step with mdBook's;
//   - package.json (below), README.md (package/README.md, the embedding guide) and LICENSE.
// The version is the crate's (Cargo.toml).

import { execFileSync } from 'node:child_process';
import { copyFileSync, cpSync, existsSync, mkdirSync, readFileSync, rmSync, statSync, writeFileSync } from 'node:fs';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { build } from 'vite';

const ROOT = join(dirname(fileURLToPath(import.meta.url)), '..');
const WWW = join(ROOT, 'www');
export const OUT = join(ROOT, 'target', 'package');
const PKG = join(OUT, 'dvf-playground');
const NAME = 'dvf-playground';

/** The element's own files and folders, copied as they are (paths relative to www/). */
const ELEMENT_FILES = ['dvf-playground.js', 'dvf-playground.d.ts', 'playground.css', 'io.js'];
const ELEMENT_DIRS = ['playground', 'render', 'panels'];
/** What of wasm-pack's output the package needs (not its package.json or README). */
const PKG_FILES = ['dvf.js', 'dvf.d.ts', 'dvf_bg.wasm', 'dvf_bg.wasm.d.ts'];
const INLINE = 'dvf-playground.inline.js';
/** Classic scripts for hosts that include no ES modules (package/). */
const CLASSIC_SCRIPTS = ['loader.js', 'mdbook.js'];

const version = readFileSync(join(ROOT, 'Cargo.toml'), 'utf8').match(/^version = "(.*)"$/m)[1];
const wasm = join(WWW, 'pkg', 'dvf_bg.wasm');
if (!existsSync(wasm)) throw new Error(`${wasm} is missing: run make build-wasm first`);

rmSync(OUT, { recursive: true, force: true });
mkdirSync(join(PKG, 'pkg'), { recursive: true });
for (const f of ELEMENT_FILES) copyFileSync(join(WWW, f), join(PKG, f));
for (const d of ELEMENT_DIRS) cpSync(join(WWW, d), join(PKG, d), { recursive: true });
for (const f of PKG_FILES) copyFileSync(join(WWW, 'pkg', f), join(PKG, 'pkg', f));
for (const f of CLASSIC_SCRIPTS) copyFileSync(join(ROOT, 'package', f), join(PKG, f));
copyFileSync(join(ROOT, 'package', 'README.md'), join(PKG, 'README.md'));
copyFileSync(join(ROOT, 'LICENSE'), join(PKG, 'LICENSE'));
writeFileSync(join(PKG, 'dvf-playground.inline.d.ts'), "export * from './dvf-playground.js';\n");

/** wasm-pack's default in pkg/dvf.js (the element always names the module itself). */
const BINDINGS_DEFAULT = "new URL('dvf_bg.wasm', import.meta.url)";
/** The results' worker as www/playground/wasm-views.js starts it (a file beside it). */
const WORKER_FILE = "new Worker(new URL('./results-worker.js', import.meta.url), { type: 'module' })";

/**
 * For the single file: pkg/dvf.js's own default dropped, so that the module is inlined once
 * (through wasm-views.js, which hands it to the worker too); and the results' worker inlined
 * (Vite's `?worker&inline`: a Blob), not a file beside it.
 * @param {boolean} main the element's bundle (else the worker's)
 */
const singleFile = (main) => ({
  name: 'dvf-single-file',
  enforce: /** @type {const} */ ('pre'),
  transform(code, id) {
    const swap = (from, to) => {
      if (!code.includes(from)) throw new Error(`${id} no longer holds ${from}: update package/build.mjs`);
      return code.replace(from, to);
    };
    if (id.endsWith('/pkg/dvf.js')) return swap(BINDINGS_DEFAULT, 'undefined');
    if (main && id.endsWith('/playground/wasm-views.js')) {
      return `import RunWorker from './results-worker.js?worker&inline';\n${swap(WORKER_FILE, 'new RunWorker()')}`;
    }
    return null;
  },
});

// The single-file variant: library mode inlines every asset the modules point at with
// `new URL('…', import.meta.url)` (the wasm module, the stylesheet) as a data URL.
await build({
  configFile: false,
  logLevel: 'warn',
  plugins: [singleFile(true)],
  worker: { format: 'es', plugins: () => [singleFile(false)] },
  build: {
    outDir: PKG,
    emptyOutDir: false,
    minify: true,
    lib: { entry: join(WWW, 'dvf-playground.js'), formats: ['es'], fileName: () => INLINE },
  },
});
const inlined = readFileSync(join(PKG, INLINE), 'utf8');
const wasmCopies = inlined.split('data:application/wasm;base64,').length - 1;
if (wasmCopies !== 1) throw new Error(`${INLINE} holds the wasm module ${wasmCopies} times, not once`);
if (existsSync(join(PKG, 'assets'))) throw new Error(`${INLINE} needs files beside it (${join(PKG, 'assets')})`);

const manifest = {
  name: NAME,
  version,
  description:
    '<dvf-playground>: live Dynamic Vector Field (DVF) multi-robot motion planning in a web page, as a custom element (WebAssembly).',
  license: 'MIT',
  type: 'module',
  main: './dvf-playground.js',
  module: './dvf-playground.js',
  types: './dvf-playground.d.ts',
  unpkg: './dvf-playground.js',
  jsdelivr: './dvf-playground.js',
  exports: {
    '.': { types: './dvf-playground.d.ts', default: './dvf-playground.js' },
    './inline': { types: './dvf-playground.inline.d.ts', default: `./${INLINE}` },
    './playground.css': './playground.css',
    './dvf_bg.wasm': './pkg/dvf_bg.wasm',
    './wasm': { types: './pkg/dvf.d.ts', default: './pkg/dvf.js' },
    './loader.js': './loader.js',
    './mdbook.js': './mdbook.js',
    './package.json': './package.json',
  },
  // Importing the element defines <dvf-playground>: a bundler must keep the import.
  sideEffects: true,
  files: [
    ...ELEMENT_FILES,
    ...ELEMENT_DIRS.map((d) => `${d}/`),
    ...PKG_FILES.map((f) => `pkg/${f}`),
    INLINE,
    'dvf-playground.inline.d.ts',
    ...CLASSIC_SCRIPTS,
  ],
  keywords: ['robotics', 'motion-planning', 'multi-robot', 'vector-field', 'webassembly', 'custom-element'],
};
writeFileSync(join(PKG, 'package.json'), `${JSON.stringify(manifest, null, 2)}\n`);

const tarball = execFileSync('npm', ['pack', '--silent', '--pack-destination', OUT], { cwd: PKG, encoding: 'utf8' })
  .trim()
  .split('\n')
  .pop();
const kb = (p) => `${(statSync(p).size / 1000).toFixed(0)} kB`;
console.log(`${join(OUT, tarball)} (${kb(join(OUT, tarball))}; ${INLINE} ${kb(join(PKG, INLINE))})`);
