// formatG is C's printf("%.*g") as glibc writes it (the expected texts below
// are glibc's snprintf output): exponent form below 1e-4 or from 10^digits
// on, trailing zeros dropped, a two-digit exponent at least, "-0", and exact
// halves rounded to even (toPrecision would round 1234567.125 up).
import assert from 'node:assert/strict';
import { test } from 'node:test';

import { formatG } from '../../dist/scene/format_g.js';

const CASES = [
    [0.0, '0', '0'],
    [-0.0, '-0', '-0'],
    [1.0, '1', '1'],
    [-1.0, '-1', '-1'],
    [0.1, '0.1', '0.1'],
    [1e-5, '1e-05', '1e-05'],
    [1.5e10, '1.5e+10', '1.5e+10'],
    [123456789.0, '123456789', '1.23e+08'],
    [1234567890.0, '1.23456789e+09', '1.23e+09'],
    [0.0001, '0.0001', '0.0001'],
    [0.00001234, '1.234e-05', '1.23e-05'],
    [5e-324, '4.94065646e-324', '4.94e-324'],
    [3.4028234663852886e38, '3.40282347e+38', '3.4e+38'],
    [1234567.125, '1234567.12', '1.23e+06'],
    [1234567.375, '1234567.38', '1.23e+06'],
    [999999999.5, '1e+09', '1e+09'],
    [9.9999999949999, '9.99999999', '10'],
    [0.000099999999995, '0.0001', '0.0001'],
    [100.0, '100', '100'],
    [1e100, '1e+100', '1e+100'],
    [-2.5e-300, '-2.5e-300', '-2.5e-300'],
    [2.675, '2.675', '2.67'],
    [1e21, '1e+21', '1e+21'],
    [123456.7890123, '123456.789', '1.23e+05'],
    [0.5, '0.5', '0.5'],
    [2.5, '2.5', '2.5'],
    [1.7976931348623157e308, '1.79769313e+308', '1.8e+308'],
];

test('formatG matches glibc printf %.9g and %.3g', () => {
    for (const [v, g9, g3] of CASES) {
        assert.equal(formatG(v, 9), g9, `%.9g of ${v}`);
        assert.equal(formatG(v, 3), g3, `%.3g of ${v}`);
    }
});

test('formatG of floats reads back exactly with 9 digits', () => {
    let seed = 12345;
    for (let i = 0; i < 2000; ++i) {
        seed = (seed * 1103515245 + 12345) % 2 ** 31;
        const v = Math.fround((seed / 2 ** 31 - 0.5) * 10 ** ((i % 60) - 30));
        assert.equal(Math.fround(Number(formatG(v, 9))), v, `${v}`);
    }
});
