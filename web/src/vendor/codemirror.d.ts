// The types of dist/vendor/codemirror.js, the CodeMirror bundle that
// tools/codemirror_entry.mjs exports (built by esbuild, not by tsc): the
// app imports it as '../vendor/codemirror.js'.
export * from '@codemirror/state';
export * from '@codemirror/view';
export * from '@codemirror/commands';
export * from '@codemirror/language';
export * from '@codemirror/lint';
export { cpp } from '@codemirror/lang-cpp';
