// The BVH (bvh.ts) on the pro scene: every sphere in exactly one leaf, every
// box around its children's or its spheres' boxes, the native tree's size
// and depth; and the 2D-texture packing web/shaders/bvh_access.glsl reads.
// (That the walk finds what the native one finds: the pro views of the
// browser tests, tests/browser/render_views.mjs, use this tree.)
import assert from 'node:assert/strict';
import { test } from 'node:test';

import { aabbContains, BVH_TEXTURE_WIDTH, buildBvh, packBvhTextures, sphereBounds } from '../../dist/scene/bvh.js';
import { loadScene } from './scene_support.mjs';

// The native build's tree for assets/scenes/pro.json has 219 nodes and is 10
// levels deep (read from the native build's tree in a debugger).
const PRO_NODES = 219;
const PRO_DEPTH = 10;

test('pro: every sphere appears exactly once among the items', () => {
    const scene = loadScene('assets/scenes/pro.json');
    const bvh = buildBvh(scene);
    assert.equal(bvh.items.length, scene.spheres.length);
    assert.deepEqual([...bvh.items].sort((a, b) => a - b), scene.spheres.map((_, i) => i));
    // ...and every item is in exactly one leaf.
    const seen = new Array(bvh.items.length).fill(0);
    for (const n of bvh.nodes) if (n.count > 0) for (let k = n.first; k < n.first + n.count; ++k) ++seen[k];
    assert.ok(seen.every((c) => c === 1));
});

test('pro: every node\'s box contains its children\'s or its spheres\' boxes', () => {
    const scene = loadScene('assets/scenes/pro.json');
    const bvh = buildBvh(scene);
    bvh.nodes.forEach((n, i) => {
        if (n.count > 0) {
            assert.ok(n.count <= 2, `leaf ${i} holds ${n.count} spheres`);
            for (let k = n.first; k < n.first + n.count; ++k)
                assert.ok(aabbContains(n.box, sphereBounds(scene, bvh.items[k])), `node ${i}, item ${k}`);
        } else {
            assert.ok(n.first > i && n.first + 1 < bvh.nodes.length, `node ${i}: children ${n.first}`);
            assert.ok(aabbContains(n.box, bvh.nodes[n.first].box), `node ${i}, left child`);
            assert.ok(aabbContains(n.box, bvh.nodes[n.first + 1].box), `node ${i}, right child`);
        }
    });
});

test('pro: the native tree\'s size and depth, two children per inner node', () => {
    const bvh = buildBvh(loadScene('assets/scenes/pro.json'));
    const leaves = bvh.nodes.filter((n) => n.count > 0).length;
    assert.equal(bvh.nodes.length, 2 * leaves - 1);
    assert.equal(bvh.nodes.length, PRO_NODES);
    assert.equal(bvh.depth, PRO_DEPTH);
});

test('a moving sphere\'s box covers its whole bob', () => {
    const scene = loadScene('assets/scenes/pro.json');
    const i = scene.spheres.findIndex((s) => s.motion.amplitude !== 0);
    assert.ok(i >= 0);
    const s = scene.spheres[i];
    const box = sphereBounds(scene, i);
    for (const sign of [-1, 1]) {
        const c = s.center.map((x, k) => x + sign * s.motion.axis[k] * s.motion.amplitude);
        for (let k = 0; k < 3; ++k) assert.ok(box.lo[k] <= c[k] - s.radius && box.hi[k] >= c[k] + s.radius);
    }
});

// texelFetch(sampler, ivec2(i % W, i / W)) on the packed data (row-major).
function texel(tex, channels, i) {
    const x = i % BVH_TEXTURE_WIDTH;
    const y = Math.floor(i / BVH_TEXTURE_WIDTH);
    assert.ok(x < tex.width && y < tex.height, `texel ${i} outside ${tex.width}x${tex.height}`);
    const at = (y * tex.width + x) * channels;
    return [...tex.data.subarray(at, at + channels)];
}

function checkPacking(bvh) {
    const { nodes, items } = packBvhTextures(bvh);
    assert.ok(nodes.data instanceof Float32Array && items.data instanceof Int32Array);
    assert.equal(nodes.data.length, nodes.width * nodes.height * 4);
    assert.equal(items.data.length, items.width * items.height);
    assert.ok(nodes.height === 1 || nodes.width === BVH_TEXTURE_WIDTH);
    assert.ok(items.height === 1 || items.width === BVH_TEXTURE_WIDTH);
    bvh.nodes.forEach((n, i) => {
        assert.deepEqual(texel(nodes, 4, 2 * i), [...n.box.lo, n.first], `bvhNodeLow(${i})`);
        // A leaf's code: 8 * count + KIND_SPHERE (0); an inner node's: 0.
        assert.deepEqual(texel(nodes, 4, 2 * i + 1), [...n.box.hi, 8 * n.count], `bvhNodeHigh(${i})`);
    });
    bvh.items.forEach((item, k) => assert.equal(texel(items, 1, k)[0], item, `bvhItem(${k})`));
}

test('packing: one row for pro, as bvh_access.glsl reads it', () => {
    const bvh = buildBvh(loadScene('assets/scenes/pro.json'));
    const { nodes, items } = packBvhTextures(bvh);
    assert.deepEqual([nodes.width, nodes.height], [2 * PRO_NODES, 1]);
    assert.deepEqual([items.width, items.height], [110, 1]);
    checkPacking(bvh);
});

test('packing: more than one row once past BVH_TEXTURE_WIDTH texels', () => {
    const scene = loadScene('assets/scenes/pro.json');
    const spheres = [];
    for (let i = 0; i < 1500; ++i) {
        const s = scene.spheres[i % scene.spheres.length];
        spheres.push({ ...s, center: [s.center[0] + 40 * Math.floor(i / 110), s.center[1], s.center[2]] });
    }
    const bvh = buildBvh({ ...scene, spheres });
    assert.ok(2 * bvh.nodes.length > 2 * BVH_TEXTURE_WIDTH && bvh.items.length > BVH_TEXTURE_WIDTH);
    const { nodes, items } = packBvhTextures(bvh);
    assert.equal(nodes.width, BVH_TEXTURE_WIDTH);
    assert.equal(nodes.height, Math.ceil((2 * bvh.nodes.length) / BVH_TEXTURE_WIDTH));
    assert.deepEqual([items.width, items.height], [BVH_TEXTURE_WIDTH, 2]);
    checkPacking(bvh);
});

test('packing: no spheres is one zero node and the item -1, as natively', () => {
    const scene = loadScene('assets/scenes/stage01.json');
    const bvh = buildBvh({ ...scene, spheres: [] });
    assert.deepEqual(bvh, { nodes: [], items: [], depth: 0 });
    const { nodes, items } = packBvhTextures(bvh);
    assert.deepEqual([nodes.width, nodes.height, [...nodes.data]], [2, 1, [0, 0, 0, 0, 0, 0, 0, 0]]);
    assert.deepEqual([items.width, items.height, [...items.data]], [1, 1, [-1]]);
});
