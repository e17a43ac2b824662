// marked (the npm registry's Markdown parser) for the guide page
// (src/app/guide.ts), bundled by `npm run build` with esbuild into
// dist/vendor/marked.js, as tools/codemirror_entry.mjs is. Its types for
// tsc: src/vendor/marked.d.ts.
export { marked } from 'marked';
