// Random scene files for the differential test (scene_random.test.mjs):
// every number kind the printer meets (tiny, huge, negative zero, decimals
// of any length), boxes turned by angles where float sinf/cosf are not
// correctly rounded (13, 19, 22 degrees...),
// directions to normalise, textures and a sky box (absolute paths to the
// project's images, so the native build finds them), 30 to 125 spheres, some
// moving, some with equal centres.
import path from 'node:path';

import { ROOT } from './scene_support.mjs';

// mulberry32: a small deterministic generator.
function generator(seed) {
    return () => {
        seed = (seed + 0x6d2b79f5) | 0;
        let t = Math.imul(seed ^ (seed >>> 15), 1 | seed);
        t = (t + Math.imul(t ^ (t >>> 7), 61 | t)) ^ t;
        return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
    };
}

// The text of scene number SEED (deterministic).
export function randomScene(seed) {
    const rnd = generator(seed);
    const pick = (a) => a[Math.floor(rnd() * a.length)];
    const raw = () => {
        const k = rnd();
        if (k < 0.1) return pick([0, -0, 1, -1, 0.5]);
        if (k < 0.2) return (rnd() - 0.5) * 1e-6;
        if (k < 0.25) return (rnd() - 0.5) * 1e12;
        if (k < 0.3) return Math.round((rnd() - 0.5) * 2000) / 8;
        return (rnd() - 0.5) * 40;
    };
    const num = () => {
        const v = raw();
        return rnd() < 0.6 ? Number(v.toPrecision(1 + Math.floor(rnd() * 12))) : v;
    };
    const v3 = () => [num(), num(), num()];
    const col = () => [rnd(), pick([0, 1, rnd()]), rnd()];
    const dir = () => {
        let d;
        do d = [rnd() - 0.5, rnd() - 0.5, rnd() - 0.5].map((x) => x * pick([1, 1e-3, 1e3]));
        while (Math.hypot(...d) < 1e-3);
        return d;
    };
    const texture = (name) => path.join(ROOT, 'assets/textures', name);
    const plain = ['zeta', 'alpha', 'Mid', 'b2', 'b10', 'émail', 'x'];
    const materials = {};
    for (const n of plain) {
        const type = pick(['plastic', 'mirror', 'glass', 'metal']);
        const m = { ambient: col(), diffuse: col(), specular: col(), shininess: rnd() * 200 + 0.001, type };
        if (type === 'glass') m.ior = 1 + rnd() * 3;
        if (type === 'metal') Object.assign(m, { n: [rnd() + 0.01, rnd() * 3 + 0.01, 2], k: [rnd() * 4, 0, rnd()] });
        materials[n] = m;
    }
    materials.tex1 = { ambient: col(), diffuse: col(), specular: col(), shininess: 5, texture: texture('earth.png'), normal_map: texture('earth_normal.png') };
    materials.tex2 = { ambient: col(), diffuse: col(), specular: col(), shininess: 5, texture: texture('moon.png') };
    const spheres = [];
    const count = Math.floor(rnd() * 90) + 30;
    for (let i = 0; i < count; ++i) {
        const s = { center: [(rnd() - 0.5) * pick([1, 50, 1000]), (rnd() - 0.5) * 20, (rnd() - 0.5) * pick([1, 50])], radius: rnd() * pick([0.01, 1, 5]) + 1e-4 };
        if (rnd() < 0.05) s.color = col();
        else s.material = pick([...plain, 'tex1', 'tex2']);
        if (rnd() < 0.3) s.motion = { axis: v3(), amplitude: num(), period: rnd() * 10 + 0.1 };
        spheres.push(s);
    }
    if (rnd() < 0.3) for (let i = 0; i < 5; ++i) spheres.push({ center: [1, 2, 3], radius: 1, color: [1, 1, 1] });
    const angle = () => pick([13, 19, 22, -188, 103, 30]) + (rnd() < 0.5 ? 0 : Math.round((rnd() - 0.5) * 7200) / 10);
    const doc = {
        comment: 'random scene',
        background: col(),
        camera: { position: v3(), yaw: num(), pitch: -0, fov_y: rnd() * 100 + 1 },
        materials,
        lights: [0, 1, 2].map(() => ({ position: v3(), color: col() })),
        spheres,
        planes: [0, 1].map(() => ({ point: v3(), normal: dir(), tile_size: rnd() * 3 + 0.1, material: pick(['tex2', ...plain]) })),
        discs: [{ center: v3(), normal: dir(), radius: rnd() + 0.1, material: pick(plain) }],
        triangles: [{ vertices: [[0, 0, 0], [1, num(), 0], [0, 1, 1]], color: col() }],
        rectangles: [{ corner: v3(), edge_u: [1 + rnd(), rnd(), 0], edge_v: [0, rnd() * 3 + 0.5, rnd()], material: pick(plain) }],
        boxes: [0, 1].map(() => ({
            center: v3(),
            size: [rnd() * 5 + 0.01, rnd() * 5 + 0.01, rnd() * pick([0.01, 5]) + 0.01],
            rotation_y: angle(),
            material: pick(plain),
        })),
        tori: [{ center: v3(), axis: dir(), major_radius: 1, minor_radius: 0.3, spin: { axis: dir(), period: 3 }, color: col() }],
        glow: { sphere: Math.floor(rnd() * count), color: col(), size: rnd() * 5 + 0.1 },
    };
    if (rnd() < 0.5) doc.sky_box = ['sky_px', 'sky_nx', 'sky_py', 'sky_ny', 'sky_pz', 'sky_nz'].map((f) => texture(`${f}.png`));
    return JSON.stringify(doc, null, 1);
}
