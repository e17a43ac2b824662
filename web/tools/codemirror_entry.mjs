// CodeMirror 6 for the page's editor (src/editor/), bundled by `npm run
// build` with esbuild into dist/vendor/codemirror.js: the browser loads the
// app's ES modules without a bundler, and CodeMirror's packages import each
// other by bare names, which only a bundler resolves. Its types for tsc:
// src/vendor/codemirror.d.ts (the same exports).
export * from '@codemirror/state';
export * from '@codemirror/view';
export * from '@codemirror/commands';
export * from '@codemirror/language';
export * from '@codemirror/lint';
export { cpp } from '@codemirror/lang-cpp';
