// C's printf("%.*g", digits, v) for a finite double, as glibc writes it:
// exact decimal expansion, rounded to DIGITS significant digits half to even
// (Number.prototype.toPrecision rounds halves up instead, so it would differ
// on exact ties such as 1234567.125), then %e or %f style by the exponent,
// without trailing zeros. The baked shader prints its floats this way
// (framework/src/core/text_format.cpp's significant()).

const TEN = 10n;

// |V| = num / den exactly (a double is an integer times a power of two).
function exactRatio(v: number): { num: bigint; den: bigint } {
    const view = new DataView(new ArrayBuffer(8));
    view.setFloat64(0, Math.abs(v));
    const bits = view.getBigUint64(0);
    const biased = Number(bits >> 52n);
    const fraction = bits & ((1n << 52n) - 1n);
    // Subnormals have no hidden bit and the exponent of the smallest normal.
    const mantissa = biased === 0 ? fraction : fraction | (1n << 52n);
    const exp2 = (biased === 0 ? 1 : biased) - 1075;
    return exp2 >= 0 ? { num: mantissa << BigInt(exp2), den: 1n } : { num: mantissa, den: 1n << BigInt(-exp2) };
}

// The DIGITS significant decimal digits of V > 0 (rounded half to even) and
// the decimal exponent of the first: V ~ 0.DIGITS * 10^(exp + 1).
function decimalDigits(v: number, digits: number): { text: string; exp: number } {
    const { num, den } = exactRatio(v);
    // The exponent E with 10^E <= v < 10^(E+1): a guess, then corrected exactly.
    let exp = Math.floor(Math.log10(v));
    const atLeast = (e: number) => (e >= 0 ? num >= den * TEN ** BigInt(e) : num * TEN ** BigInt(-e) >= den);
    while (!atLeast(exp)) --exp;
    while (atLeast(exp + 1)) ++exp;
    // q = v * 10^(digits - 1 - exp), an integer of DIGITS digits, plus a remainder.
    const shift = digits - 1 - exp;
    const n = shift >= 0 ? num * TEN ** BigInt(shift) : num;
    const d = shift >= 0 ? den : den * TEN ** BigInt(-shift);
    let q = n / d;
    const twice = 2n * (n % d);
    if (twice > d || (twice === d && q % 2n === 1n)) ++q;
    if (q === TEN ** BigInt(digits)) {
        // Rounded up to the next power of ten: 9.995 -> 10.0.
        q = TEN ** BigInt(digits - 1);
        ++exp;
    }
    return { text: q.toString(), exp };
}

function withoutTrailingZeros(s: string): string {
    return s.replace(/0+$/, '');
}

export function formatG(v: number, digits: number): string {
    if (!Number.isFinite(v)) return Number.isNaN(v) ? 'nan' : v < 0 ? '-inf' : 'inf';
    const p = digits === 0 ? 1 : digits;
    const sign = v < 0 || Object.is(v, -0) ? '-' : '';
    if (v === 0) return `${sign}0`;
    const { text, exp } = decimalDigits(Math.abs(v), p);
    if (exp < -4 || exp >= p) {
        const rest = withoutTrailingZeros(text.slice(1));
        const e = Math.abs(exp).toString().padStart(2, '0');
        return `${sign}${text[0]}${rest ? '.' + rest : ''}e${exp < 0 ? '-' : '+'}${e}`;
    }
    if (exp < 0) return `${sign}0.${'0'.repeat(-exp - 1)}${withoutTrailingZeros(text)}`;
    const whole = text.slice(0, exp + 1);
    const fraction = withoutTrailingZeros(text.slice(exp + 1));
    return `${sign}${whole}${fraction ? '.' + fraction : ''}`;
}
