// `vite dev` pre-bundles dependencies into a folder of its own, away from the wasm module and
// the stylesheet the element finds beside its modules: keep the package out of it.
export default { optimizeDeps: { exclude: ['dvf-playground'] } };
