// A ray-tracing scene as the native build holds it
// (framework/src/raytrace/scene/scene.h): background, camera, materials,
// lights and objects, read from the same JSON files (scene_reader.ts).
// Numbers are the native floats: every stored number went through
// Math.fround, and the little maths below repeats glm's float operations
// (float32.ts), so uniforms and baked constants match the native ones.
import { cross, f32, fmod32, normalize, rotation, sinf, scale, transform } from './float32.js';

export type Vec3 = [number, number, number];

// A sinusoidal bob: offset = axis * amplitude * sin(2 pi t / period).
export interface Motion {
    axis: Vec3;
    amplitude: number;
    periodSeconds: number;
}

// Material.type: how light leaves the surface besides Blinn-Phong.
export const MaterialType = { Plastic: 0, Mirror: 1, Glass: 2, Metal: 3 } as const;
export type MaterialType = (typeof MaterialType)[keyof typeof MaterialType];

export interface Material {
    name: string;
    type: MaterialType;
    ior: number; // glass: index of refraction
    n: Vec3; // metal: complex index n + ik per RGB channel
    k: Vec3;
    ambient: Vec3;
    diffuse: Vec3; // also the flat colour of stage 01
    specular: Vec3;
    shininess: number;
    texture: number; // index into Scene.textures, -1: none
    normalMap: number; // index into Scene.textures, -1: none
}

export interface PointLight {
    position: Vec3;
    color: Vec3;
}

export interface Sphere {
    center: Vec3;
    radius: number;
    material: number; // index into Scene.materials
    motion: Motion;
}

// An infinite plane through `point`; textures repeat every `tileSize` units.
export interface Plane {
    point: Vec3;
    normal: Vec3; // unit
    tileSize: number;
    material: number;
}

export interface Disc {
    center: Vec3;
    normal: Vec3; // unit
    radius: number;
    material: number;
}

// Counter-clockwise seen from the side the normal points to.
export interface Triangle {
    vertices: [Vec3, Vec3, Vec3];
    material: number;
}

// A ring around `axis` through `center`; with a spin (spinPeriod > 0) the
// axis turns about `spinAxis` once every `spinPeriod` seconds.
export interface Torus {
    center: Vec3;
    axis: Vec3; // unit
    majorRadius: number;
    minorRadius: number;
    spinAxis: Vec3;
    spinPeriod: number; // 0: no spin
    material: number;
}

// A halo drawn around a sphere (the "sun").
export interface Glow {
    sphere: number; // -1: none
    color: Vec3;
    size: number; // in sphere radii
}

export interface CameraPose {
    position: Vec3;
    yawDeg: number; // 0 looks down -z, 90 looks down +x
    pitchDeg: number; // positive looks up
}

export interface Scene {
    file: string; // as shown in messages and in the baked shader's first line
    background: Vec3;
    camera: CameraPose;
    fovYDeg: number;
    materials: Material[];
    lights: PointLight[];
    spheres: Sphere[];
    planes: Plane[];
    discs: Disc[];
    triangles: Triangle[];
    tori: Torus[];
    // Image URLs (resolved against the scene file's URL), one texture layer
    // each; a file named twice shares its layer.
    textures: string[];
    skyBox: string[] | null; // six URLs: +x, -x, +y, -y, +z, -z
    glow: Glow;
}

// The C++ constants, as floats.
const TWO_PI = f32(6.28318530718);
export const DEFAULT_FOV_Y_DEG = f32(36.87);

// Motion::offsetAt: axis * amplitude * sin(2 pi t / period), in float.
export function offsetAt(motion: Motion, t: number): Vec3 {
    if (motion.amplitude === 0) return [0, 0, 0];
    const phase = f32(f32(TWO_PI * f32(t)) / motion.periodSeconds);
    return scale(scale(motion.axis, motion.amplitude), sinf(phase));
}

// Torus::axisAt (scene_shapes.cpp): the axis turned about spinAxis by
// 2 pi * fmod(t / period, 1), with glm::rotate's own arithmetic.
export function torusAxisAt(torus: Torus, t: number): Vec3 {
    if (torus.spinPeriod <= 0) return torus.axis;
    const angle = f32(TWO_PI * fmod32(f32(f32(t) / torus.spinPeriod), 1));
    const a = transform(rotation(angle, torus.spinAxis), [...torus.axis, 0]);
    return normalize([a[0]!, a[1]!, a[2]!]);
}

// torusToLocal (stage_renderer.cpp): the world-to-local rotation that turns
// AXIS into +z, rows x, y, axis. Returned column-major (9 numbers), as
// gl.uniformMatrix3fv(location, false, ...) takes it: column j holds
// (x[j], y[j], axis[j]).
export function torusToLocal(axis: Vec3): number[] {
    const helper: Vec3 = Math.abs(axis[0]) < f32(0.9) ? [1, 0, 0] : [0, 1, 0];
    const x = normalize(cross(helper, axis));
    const y = cross(axis, x);
    return [x[0], y[0], axis[0], x[1], y[1], axis[1], x[2], y[2], axis[2]];
}
