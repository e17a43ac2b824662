// JSON for scene files: the browser's own parser (JSON.parse), with the
// native reader's (nlohmann::json's) view of the result:
//  - objects iterate in std::map order, sorted by key (objectKeys): the
//    order in which materials get their indices natively;
//  - numbers are JsonNumber, with whether they are whole (glow.sphere must
//    be; natively "1.0" is not, here it is - the one difference);
//  - a number too large for a double ("1e500") is an error, not Infinity;
//  - a syntax error names the line and column where the parser stopped.
export class JsonNumber {
    constructor(
        readonly value: number,
        readonly isInteger: boolean,
    ) {}
}

export type JsonObject = Map<string, Json>;
export type Json = null | boolean | string | JsonNumber | Json[] | JsonObject;

export function isObject(v: Json | undefined): v is JsonObject {
    return v instanceof Map;
}

// The keys of OBJ in nlohmann::json's (std::map's) order: by UTF-8 bytes.
export function objectKeys(obj: JsonObject): string[] {
    const encoder = new TextEncoder();
    const keyed = [...obj.keys()].map((k) => ({ k, bytes: encoder.encode(k) }));
    keyed.sort((a, b) => compareBytes(a.bytes, b.bytes));
    return keyed.map((x) => x.k);
}

function compareBytes(a: Uint8Array, b: Uint8Array): number {
    const n = Math.min(a.length, b.length);
    for (let i = 0; i < n; ++i) if (a[i] !== b[i]) return a[i]! - b[i]!;
    return a.length - b.length;
}

// "syntax": at LINE, COLUMN (1-based; 0 when the parser did not say where),
// with the parser's own words. "range": a number that does not fit a double.
export class JsonParseError extends Error {
    constructor(
        readonly kind: 'syntax' | 'range',
        readonly line = 0,
        readonly column = 0,
        readonly detail = '',
    ) {
        const where = line > 0 ? `line ${line}, column ${column}: ` : '';
        super(kind === 'range' ? 'JSON number out of range' : `${where}JSON syntax error${detail ? ` (${detail})` : ''}`);
    }
}

function convert(v: unknown): Json {
    if (v === null || typeof v === 'boolean' || typeof v === 'string') return v;
    if (typeof v === 'number') {
        if (!Number.isFinite(v)) throw new JsonParseError('range');
        return new JsonNumber(v, Number.isInteger(v));
    }
    if (Array.isArray(v)) return v.map(convert);
    const map: JsonObject = new Map();
    for (const [k, x] of Object.entries(v as Record<string, unknown>)) map.set(k, convert(x));
    return map;
}

// The line and column of character POSITION of TEXT.
function lineColumn(text: string, position: number): [number, number] {
    const before = text.slice(0, position);
    const line = before.split('\n').length;
    return [line, position - before.lastIndexOf('\n')];
}

// The JSON document in TEXT. Throws JsonParseError.
export function parseJson(text: string): Json {
    let raw: unknown;
    try {
        raw = JSON.parse(text);
    } catch (e) {
        // V8: "Expected ',' or '}' after property value in JSON at position 30",
        // "Unexpected end of JSON input", or without a position:
        // "Unexpected token ']', "[1,]" is not valid JSON".
        const message = String((e as Error).message).split('\n')[0]!;
        const detail = message.replace(/ in JSON at position \d+.*$/, '').replace(/, ".*" is not valid JSON$/, '');
        const at = /position (\d+)/.exec(message);
        if (at) throw new JsonParseError('syntax', ...lineColumn(text, Number(at[1])), detail);
        if (/end of JSON input/.test(message)) throw new JsonParseError('syntax', ...lineColumn(text, text.length), detail);
        throw new JsonParseError('syntax', 0, 0, detail);
    }
    return convert(raw);
}
