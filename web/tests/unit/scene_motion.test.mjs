// Per-frame scene values: sphere bobs (offsetAt), torus spin (torusAxisAt),
// the torus's world-to-local matrix (torusToLocal), checked against values
// worked out by hand and against the native build's floats (within a bit:
// C libraries' sinf differs from the nearest float now and then).
import assert from 'node:assert/strict';
import { test } from 'node:test';

import { offsetAt, torusAxisAt, torusToLocal } from '../../dist/scene/scene.js';

const f = Math.fround;
const near = (a, b, eps = 1e-6) => a.forEach((x, i) => assert.ok(Math.abs(x - b[i]) <= eps, `${a} vs ${b}`));

test('offsetAt: axis * amplitude * sin(2 pi t / period)', () => {
    const motion = { axis: [0, 1, 0], amplitude: 0.4, periodSeconds: 6 };
    assert.deepEqual(offsetAt({ ...motion, amplitude: 0 }, 1.5), [0, 0, 0]);
    assert.deepEqual(offsetAt(motion, 0), [0, 0, 0]);
    near(offsetAt(motion, 1.5), [0, 0.4, 0]); // a quarter period: the full amplitude
    near(offsetAt(motion, 4.5), [0, -0.4, 0]); // three quarters: the other way
    near(offsetAt(motion, 0.5), [0, 0.4 * Math.sin(Math.PI / 6), 0]); // sin 30 deg = 1/2
    near(offsetAt({ axis: [1, 0, 0], amplitude: 2, periodSeconds: 4 }, 1), [2, 0, 0]);
    // The native float result of offsetAt(axis (0, 1, 0), 0.4, period 6) at t = 1.7 (gdb).
    near(offsetAt(motion, 1.7), [0, 0.3912590444087982, 0], 1e-7);
    for (const v of offsetAt(motion, 1.2345)) assert.equal(v, f(v), 'floats');
});

test('torusAxisAt: the axis turned about the spin axis, 2 pi * fmod(t / period, 1)', () => {
    const torus = { center: [0, 0, 0], axis: [1, 0, 0], majorRadius: 1, minorRadius: 0.2, spinAxis: [0, 1, 0], spinPeriod: 8, material: 0 };
    assert.deepEqual(torusAxisAt({ ...torus, spinPeriod: 0 }, 3), [1, 0, 0]);
    assert.deepEqual(torusAxisAt(torus, 0), [1, 0, 0]);
    near(torusAxisAt(torus, 2), [0, 0, -1]); // a quarter turn about +y takes +x to -z
    near(torusAxisAt(torus, 4), [-1, 0, 0]);
    near(torusAxisAt(torus, 6), [0, 0, 1]);
    near(torusAxisAt(torus, 10), [0, 0, -1]); // fmod: the second turn repeats the first
    near(torusAxisAt(torus, 1), [Math.SQRT1_2, 0, -Math.SQRT1_2]);
    const tilted = { ...torus, axis: [0, 1, 0], spinAxis: [1, 0, 0] };
    near(torusAxisAt(tilted, 2), [0, 0, 1]); // +y about +x: to +z
    // The native float result for pro.json's torus at t = 1.7 (gdb).
    const pro = { ...torus, axis: [0.3215206563472748, 0.9186304211616516, 0.2296576052904129], spinAxis: [0, 1, 0], spinPeriod: 8 };
    near(torusAxisAt(pro, 1.7), [0.2983696460723877, 0.9186305403709412, -0.2590245306491852], 1e-7);
});

test('torusToLocal: column-major rows x, y, axis; takes the axis to +z', () => {
    // The -0s are glm's: cross() computes 0 * -1 - 0 * 0.
    assert.deepEqual(torusToLocal([0, 0, 1]), [0, 1, 0, -1, 0, 0, 0, -0, 1]);
    assert.deepEqual(torusToLocal([1, 0, 0]), [0, -0, 1, 0, 1, 0, -1, 0, 0]);
    const apply = (m, v) => [0, 1, 2].map((r) => m[r] * v[0] + m[3 + r] * v[1] + m[6 + r] * v[2]);
    for (const a of [[0.3215206563472748, 0.9186304211616516, 0.2296576052904129], [0.95, 0.3122498999199199, 0], [0, -1, 0]]) {
        const m = torusToLocal(a);
        near(apply(m, a), [0, 0, 1]);
        for (let i = 0; i < 3; ++i) for (let j = 0; j < 3; ++j) {
            const dot = m[i] * m[j] + m[3 + i] * m[3 + j] + m[6 + i] * m[6 + j];
            assert.ok(Math.abs(dot - (i === j ? 1 : 0)) < 1e-6, 'orthonormal');
        }
    }
});
