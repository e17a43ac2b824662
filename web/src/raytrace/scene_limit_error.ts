// A scene larger than the stage or the browser allows: one line, shown on the page.
export class SceneLimitError extends Error {}
