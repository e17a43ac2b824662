// The constants GLSL and C++ share (framework/src/core/shader_constants.h),
// emitted exactly as the native assembler emits them. The web tests compare
// the whole assembled shader with `raylab shader --es`, so a constant changed
// on one side only fails there.
export const NO_HIT = -1.0;
export const T_MIN = 1e-4;
export const T_FAR = 1e30;
export const MAX_DEPTH = 8;
export const MAX_RAYS = 1 << MAX_DEPTH;
export const OBJECT_KIND_STRIDE = 1 << 20;
const KINDS = ['SPHERE', 'PLANE', 'DISC', 'TRIANGLE', 'TORUS', 'MESH'];

// C's "%.9g" for the few values above, always written as a float literal.
function floatLiteral(v: number): string {
  let s = v.toPrecision(9);
  if (s.includes('e')) {
    const [m, e] = s.split('e');
    const mant = m.includes('.') ? m.replace(/0+$/, '').replace(/\.$/, '') : m;
    const exp = Number(e);
    s = `${mant}e${exp < 0 ? '-' : '+'}${String(Math.abs(exp)).padStart(2, '0')}`;
  } else if (s.includes('.')) {
    s = s.replace(/0+$/, '').replace(/\.$/, '');
  }
  return /[.eEn]/.test(s) ? s : s + '.0';
}

export function constantsGlsl(): string {
  const f = (name: string, v: number) => `const float ${name} = ${floatLiteral(v)};\n`;
  const i = (name: string, v: number) => `const int ${name} = ${v};\n`;
  return (
    f('NO_HIT', NO_HIT) +
    // A stage may set its own T_MIN (stage.json "defines": RAYLAB_T_MIN), as natively.
    '#ifdef RAYLAB_T_MIN\nconst float T_MIN = RAYLAB_T_MIN;\n#else\n' + f('T_MIN', T_MIN) + '#endif\n' +
    f('T_FAR', T_FAR) +
    i('MAX_DEPTH', MAX_DEPTH) + i('MAX_RAYS', MAX_RAYS) +
    KINDS.map((k, n) => i(`KIND_${k}`, n)).join('') +
    i('OBJECT_KIND_STRIDE', OBJECT_KIND_STRIDE)
  );
}
