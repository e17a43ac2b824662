// Scene JSON goes through the browser's JSON.parse, seen the way the native
// reader (nlohmann::json) sees it: a syntax error names its line (the
// column is where the parser stopped), a number beyond a double is its own
// error, object keys come out sorted (std::map order: material indices),
// numbers know whether they are whole.
import assert from 'node:assert/strict';
import { test } from 'node:test';

import { JsonNumber, objectKeys, parseJson } from '../../dist/scene/json_parse.js';
import { parseJsonText, SceneError } from '../../dist/scene/json_reader.js';

function messageFor(text) {
    try {
        parseJsonText(text, 'F');
        return null;
    } catch (e) {
        assert.ok(e instanceof SceneError, String(e));
        assert.ok(e.message.startsWith('F: '), e.message);
        return e.message.slice(3);
    }
}

// [name, text, the line of the error; 0: the parser names the token, not where]
const SYNTAX = [
    ['empty', '', 1],
    ['open brace', '{', 1],
    ['trailing comma in array', '[1,]', 0],
    ['missing colon', '{"a" 1}', 1],
    ['leading zero', '[01]', 1],
    ['unterminated string', '"abc', 1],
    ['garbage after', '{} x', 1],
    ['newlines', '{\n  "a": [\n    1,\n    2\n  ]\n  "b": 3\n}', 6],
    ['CRLF', '{\r\n  "a": 1,\r\n  oops\r\n}', 3],
    ['unclosed object after key', '{\n"a":', 2],
];

test('a syntax error names the line it is on', () => {
    for (const [name, text, line] of SYNTAX) {
        const m = messageFor(text);
        const where = line ? `line ${line}, column \\d+: ` : '';
        assert.match(m ?? '', new RegExp(`^${where}JSON syntax error \\(\\S.*\\)$`), name);
        assert.ok(!m.includes('\n'), `${name}: one line`);
    }
});

test('a number beyond a double is its own error; a good document parses', () => {
    assert.equal(messageFor('[1e400]'), 'JSON number out of range (larger than a double can hold)');
    assert.equal(messageFor(`[${'9'.repeat(400)}]`), 'JSON number out of range (larger than a double can hold)');
    assert.equal(messageFor('{"a": [1, 2.5, "x", null, true]}'), null);
});

test('values: integers flagged, keys sorted by bytes, the last duplicate wins', () => {
    const doc = parseJson('{"b": 1, "a": [1.5, -0.0, 7], "B": true, "é": null, "b": 2}');
    assert.deepEqual(objectKeys(doc), ['B', 'a', 'b', 'é']);
    assert.deepEqual(doc.get('b'), new JsonNumber(2, true));
    const [half, negZero, seven] = doc.get('a');
    assert.equal(half.isInteger, false);
    assert.ok(Object.is(negZero.value, -0));
    assert.equal(seven.isInteger, true);
});

test('strings: escapes and surrogate pairs decode', () => {
    assert.equal(parseJson('"a\\"\\\\\\/\\b\\f\\n\\r\\t\\u00e9\\ud83d\\ude00"'), 'a"\\/\b\f\n\r\té😀');
});
