// The command-line options of the wasm benchmarks (`wasm.mjs`, `wasm-chromium.mjs`, `wasm-native.mjs`).

/** The value after `--name`, as a whole number, or `fallback`; exits with a message otherwise. */
export function option(name, fallback) {
  const at = process.argv.indexOf(`--${name}`);
  if (at < 0) return fallback;
  const value = Number(process.argv[at + 1]);
  if (!Number.isInteger(value) || value < 0) {
    console.error(`${name}: expected a whole number, not ${process.argv[at + 1]}`);
    process.exit(2);
  }
  return value;
}
