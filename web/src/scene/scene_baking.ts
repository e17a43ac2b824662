// A shader specialised for one scene: its static data written into the GLSL
// as constants instead of uniforms, character for character as the native
// build writes it (framework/src/raytrace/scene/scene_baking.cpp), so both
// builds compile the same shader. Moving data (sphere positions, torus axes)
// and the run-time switches stay uniforms.
import { dot, f32 } from './float32.js';
import { formatG } from './format_g.js';
import { Scene, Vec3 } from './scene.js';
import { triangleGroups } from './triangle_groups.js';

// A float literal GLSL reads back as exactly the same float: 9 significant
// digits (%.9g), and always with a '.' or an exponent (a bare "1" would be
// an int).
export function floatLiteral(v: number): string {
    const s = formatG(f32(v), 9);
    return /[.e]/.test(s) ? s : `${s}.0`;
}

function vec3Literal(v: Vec3): string {
    return `vec3(${v.map(floatLiteral).join(', ')})`;
}
function vec4Literal(v: number[]): string {
    return `vec4(${v.map(floatLiteral).join(', ')})`;
}

// "const TYPE NAME[N] = TYPE[N](a, b, ...);" - with one dummy element when
// the list is empty (the shader still declares the array).
function constArray(type: string, name: string, values: string[], dummy: string): string {
    const n = Math.max(1, values.length);
    const items = values.length ? values.join(', ') : dummy;
    return `const ${type} ${name}[${n}] = ${type}[${n}](${items});\n`;
}
const floats = (name: string, v: number[]) => constArray('float', name, v.map(floatLiteral), '0.0');
const ints = (name: string, v: number[]) => constArray('int', name, v.map(String), '0');
const vec3s = (name: string, v: Vec3[]) => constArray('vec3', name, v.map(vec3Literal), 'vec3(0.0)');
const vec4s = (name: string, v: number[][]) => constArray('vec4', name, v.map(vec4Literal), 'vec4(0.0)');
const constInt = (name: string, v: number) => `const int ${name} = ${v};\n`;

// The GLSL constants (one declaration per line) for SCENE. SHOWNFILE names
// the scene file in the first line as the native build shows it
// ("assets/scenes/lite.json"); by default the name the scene was read with.
export function bakedSceneGlsl(scene: Scene, shownFile: string = scene.file): string {
    let g = `// The scene, compiled in (framework/src/raytrace/scene/scene_baking.cpp): ${shownFile}\n`;
    g += `const vec3 uBackground = ${vec3Literal(scene.background)};\n`;

    g += constInt('uSphereCount', scene.spheres.length);
    g += vec3s('uSphereColors', scene.spheres.map((s) => scene.materials[s.material]!.diffuse));
    g += ints('uSphereMaterial', scene.spheres.map((s) => s.material));

    const m = scene.materials;
    g += vec3s('uMatAmbient', m.map((x) => x.ambient));
    g += vec3s('uMatDiffuse', m.map((x) => x.diffuse));
    g += vec3s('uMatSpecular', m.map((x) => x.specular));
    g += floats('uMatShininess', m.map((x) => x.shininess));
    g += ints('uMatType', m.map((x) => x.type));
    g += floats('uMatIor', m.map((x) => x.ior));
    g += vec3s('uMatN', m.map((x) => x.n));
    g += vec3s('uMatK', m.map((x) => x.k));
    g += ints('uMatTexture', m.map((x) => x.texture));
    g += ints('uMatNormalMap', m.map((x) => x.normalMap));

    g += constInt('uLightCount', scene.lights.length);
    g += vec3s('uLightPositions', scene.lights.map((l) => l.position));
    g += vec3s('uLightColors', scene.lights.map((l) => l.color));

    g += constInt('uPlaneCount', scene.planes.length);
    g += vec4s('uPlanes', scene.planes.map((p) => [...p.normal, dot(p.normal, p.point)]));
    g += floats('uPlaneTileSize', scene.planes.map((p) => p.tileSize));
    g += ints('uPlaneMaterial', scene.planes.map((p) => p.material));

    g += constInt('uDiscCount', scene.discs.length);
    g += vec4s('uDiscs', scene.discs.map((d) => [...d.center, d.radius]));
    g += vec3s('uDiscNormals', scene.discs.map((d) => d.normal));
    g += ints('uDiscMaterial', scene.discs.map((d) => d.material));

    g += constInt('uTriangleCount', scene.triangles.length);
    g += vec3s('uTriangleVertices', scene.triangles.flatMap((t) => t.vertices));
    g += ints('uTriangleMaterial', scene.triangles.map((t) => t.material));
    const groups = triangleGroups(scene);
    g += constInt('uTriangleGroupCount', groups.length);
    g += vec4s('uTriangleGroupLow', groups.map((t) => [...t.lo, t.first]));
    g += vec4s('uTriangleGroupHigh', groups.map((t) => [...t.hi, t.count]));

    g += constInt('uTorusCount', scene.tori.length);
    g += vec4s('uTori', scene.tori.map((t) => [...t.center, t.majorRadius]));
    g += floats('uTorusMinor', scene.tori.map((t) => t.minorRadius));
    g += ints('uTorusMaterial', scene.tori.map((t) => t.material));

    g += constInt('uHasSky', scene.skyBox ? 1 : 0);
    g += constInt('uGlowSphere', scene.glow.sphere);
    g += `const vec3 uGlowColor = ${vec3Literal(scene.glow.color)};\n`;
    g += `const float uGlowSize = ${floatLiteral(scene.glow.size)};\n`;
    return g;
}

// SCENE_BAKED and MAX_SPHERES, MAX_PLANES, ... set to the scene's own counts
// (at least 1: GLSL has no empty arrays), as "NAME VALUE" for #define lines.
export function bakedSceneDefines(scene: Scene): string[] {
    const size = (name: string, n: number) => `${name} ${Math.max(1, n)}`;
    return [
        'SCENE_BAKED',
        size('MAX_SPHERES', scene.spheres.length),
        size('MAX_MATERIALS', scene.materials.length),
        size('MAX_LIGHTS', scene.lights.length),
        size('MAX_PLANES', scene.planes.length),
        size('MAX_DISCS', scene.discs.length),
        size('MAX_TRIANGLES', scene.triangles.length),
        size('MAX_TORI', scene.tori.length),
    ];
}
