// The types of dist/vendor/marked.js (tools/marked_entry.mjs, built by
// esbuild, not by tsc): the guide page imports it as '../vendor/marked.js'.
export { marked } from 'marked';
