// A number in an OBJ file, read as the native build's tinyobjloader (Debian
// 2.0.0~rc10, float real_t) reads it: its own tryParseDouble, which is not
// correctly rounded ("1.23" is 1 + 2 * 0.1 + 3 * 0.01 in double), then cast
// to float. Repeating its arithmetic gives the native floats; JSON.parse or
// Number() would now and then differ in the last bit.
//
// One difference: tinyobjloader stops at the first character that is not
// part of a number and quietly reads "1.5abc" as 1.5 and "abc" as 0; here
// the whole token must be a number, or parseObjNumber returns null.

const NUMBER = /^[+-]?(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?$/;
const POW_LUT = [1.0, 0.1, 0.01, 0.001, 0.0001, 0.00001, 0.000001, 0.0000001];
const INT_MAX = 2147483647;

const isDigit = (c: string | undefined) => c !== undefined && c >= '0' && c <= '9';

// glibc's pow(10, -n) and pow(5, n) are correctly rounded (in all cases
// that matter here); these are too, where V8's Math.pow need not be.
function tenToMinus(n: number): number {
    return Number(`1e-${n}`);
}
function fivePow(e: number): number {
    if (e >= 0) return e > 1100 ? Infinity : Number(5n ** BigInt(e));
    // 5^-k = 10^-k * 2^k, exact scaling while 10^-k is a normal double.
    return -e <= 300 ? tenToMinus(-e) * 2 ** -e : Math.pow(5, e);
}
function ldexp(x: number, e: number): number {
    if (e >= -1022 && e <= 1023) return x * 2 ** e;
    const half = Math.trunc(e / 2);
    return x * 2 ** half * 2 ** (e - half);
}

// The float that tinyobjloader makes of TOKEN, or null when TOKEN is not a
// number (or its exponent overflows an int, which tinyobjloader refuses).
export function parseObjNumber(token: string): number | null {
    if (!NUMBER.test(token)) return null;
    let i = 0;
    let sign = 1;
    if (token[0] === '+' || token[0] === '-') {
        sign = token[0] === '-' ? -1 : 1;
        ++i;
    }
    let mantissa = 0;
    for (; isDigit(token[i]); ++i) {
        mantissa *= 10;
        mantissa += token.charCodeAt(i) - 48;
    }
    if (token[i] === '.') {
        ++i;
        for (let read = 1; isDigit(token[i]); ++read, ++i)
            mantissa += (token.charCodeAt(i) - 48) * (read < POW_LUT.length ? POW_LUT[read]! : tenToMinus(read));
    }
    let exponent = 0;
    if (token[i] === 'e' || token[i] === 'E') {
        ++i;
        let expSign = 1;
        if (token[i] === '+' || token[i] === '-') expSign = token[i++] === '-' ? -1 : 1;
        for (; isDigit(token[i]); ++i) {
            if (exponent > Math.floor(INT_MAX / 10)) return null;
            exponent = exponent * 10 + (token.charCodeAt(i) - 48);
            if (exponent > INT_MAX) return null; // signed overflow natively
        }
        exponent *= expSign;
    }
    return Math.fround(sign * (exponent ? ldexp(mantissa * fivePow(exponent), exponent) : mantissa));
}
