// The bounding volume hierarchy over a scene's spheres, built exactly as the
// native build builds it (framework/src/raytrace/scene/bvh.cpp: binned SAH,
// 12 bins, at most 2 spheres a leaf, libstdc++'s std::partition order, float
// arithmetic), so both builds walk the same tree. Moving spheres: a sphere's
// box covers its whole bob, so one tree holds at every time.
//
// On the GPU (packBvhTextures) - WebGL 2 has no buffer textures, so the two
// native buffer textures (framework/src/raytrace/bvh_buffers.cpp) become 2D
// textures that web/shaders/bvh_access.glsl reads with texelFetch:
//   element i of either lies at texel (i % BVH_TEXTURE_WIDTH, i / BVH_TEXTURE_WIDTH),
//   rows filled one after the other (row 0 first = the first row uploaded).
//   uBvhNodes, RGBA32F: element 2n = (box.lo.xyz, first), 2n + 1 = (box.hi.xyz, code)
//     for node n; a leaf's code is 8 * count + KIND_SPHERE (0): it holds items
//     first .. first + count - 1; an inner node (code 0) has its children at
//     nodes first and first + 1.
//   uBvhItems, R32I: element k = the sphere index of item k.
// A texture is BVH_TEXTURE_WIDTH texels wide once it needs more than one
// row; a single row is only as wide as its elements (i % 1024 = i there).
// Unused texels of the last row are 0. An empty tree (no spheres) packs one
// zero node and the item -1, as the native build does: no texture is empty.
import { absf, add, f32, scale, splat, sub, vabs, vmax, vmin } from './float32.js';
import { Scene, Vec3 } from './scene.js';

export const BVH_TEXTURE_WIDTH = 1024; // as in web/shaders/bvh_access.glsl
export const BVH_MAX_DEPTH = 32; // the GLSL traversal stack (bvh.h's kBvhMaxDepth)
// A leaf's code is BVH_LEAF_KINDS * count + its items' kind (bvh_buffers.h's
// kBvhLeafKinds); the web's tree holds spheres only, KIND_SPHERE = 0.
export const BVH_LEAF_KINDS = 8;

export interface Aabb {
    lo: Vec3;
    hi: Vec3;
}
export interface BvhNode {
    box: Aabb;
    first: number;
    count: number; // > 0: a leaf
}
export interface Bvh {
    nodes: BvhNode[]; // nodes[0] is the root (none when there are no spheres)
    items: number[]; // sphere indices
    depth: number; // longest root-to-leaf path, in nodes
}

const BIG = f32(1e30);
const FLT_MAX = 3.4028234663852886e38;
const BINS = 12;

function emptyBox(): Aabb {
    return { lo: splat(BIG), hi: splat(-BIG) };
}
function grow(a: Aabb, b: Aabb): void {
    a.lo = vmin(a.lo, b.lo);
    a.hi = vmax(a.hi, b.hi);
}
function growPoint(a: Aabb, p: Vec3): void {
    a.lo = vmin(a.lo, p);
    a.hi = vmax(a.hi, p);
}
function centre(a: Aabb): Vec3 {
    return scale(add(a.lo, a.hi), 0.5);
}
// Surface area (0 for an empty box).
function area(a: Aabb): number {
    const e = sub(a.hi, a.lo);
    if (e[0] < 0 || e[1] < 0 || e[2] < 0) return 0;
    return f32(2 * f32(f32(f32(e[0] * e[1]) + f32(e[1] * e[2])) + f32(e[2] * e[0])));
}
export function aabbContains(a: Aabb, b: Aabb): boolean {
    return [0, 1, 2].every((i) => a.lo[i]! <= b.lo[i]! && a.hi[i]! >= b.hi[i]!);
}

// The box of sphere INDEX over all times, a little padded: float rounding in
// the GLSL slab test must never cut off a surface that touches the box.
export function sphereBounds(scene: Scene, index: number): Aabb {
    const s = scene.spheres[index]!;
    const sweep = scale(vabs(s.motion.axis), absf(s.motion.amplitude));
    const lo = sub(sub(s.center, splat(s.radius)), sweep);
    const hi = add(add(s.center, splat(s.radius)), sweep);
    const pad = add(scale(add(vabs(lo), vabs(hi)), f32(1e-4)), splat(f32(1e-5)));
    return { lo: sub(lo, pad), hi: add(hi, pad) };
}

class Builder {
    boxes: Aabb[] = []; // per item
    centres: Vec3[] = [];
    order: number[] = []; // item indices, partitioned in place
    nodes: BvhNode[] = [];
    depth = 0;

    constructor(private readonly maxLeaf: number) {}

    boundsOf(begin: number, end: number): Aabb {
        const b = emptyBox();
        for (let i = begin; i < end; ++i) grow(b, this.boxes[this.order[i]!]!);
        return b;
    }

    // The bin of ITEM's centre along AXIS within the centres' box.
    binOf(item: number, axis: number, centreBox: Aabb): number {
        const lo = centreBox.lo[axis]!;
        const hi = centreBox.hi[axis]!;
        const b = Math.trunc(f32(f32(BINS * f32(this.centres[item]![axis]! - lo)) / f32(hi - lo)));
        return Math.min(Math.max(b, 0), BINS - 1);
    }

    // Binned SAH split of items [begin, end): partitions them and returns the
    // split position, or -1 when one leaf is cheaper (and allowed).
    split(begin: number, end: number, box: Aabb): number {
        const n = end - begin;
        const centreBox = emptyBox();
        for (let i = begin; i < end; ++i) growPoint(centreBox, this.centres[this.order[i]!]!);
        let bestCost = FLT_MAX;
        let bestAxis = -1;
        let bestBin = 0;
        for (let axis = 0; axis < 3; ++axis) {
            if (f32(centreBox.hi[axis]! - centreBox.lo[axis]!) < f32(1e-12)) continue;
            const bins = Array.from({ length: BINS }, emptyBox);
            const counts = new Array<number>(BINS).fill(0);
            for (let i = begin; i < end; ++i) {
                const item = this.order[i]!;
                const b = this.binOf(item, axis, centreBox);
                grow(bins[b]!, this.boxes[item]!);
                ++counts[b]!;
            }
            for (let cut = 1; cut < BINS; ++cut) {
                const left = emptyBox();
                const right = emptyBox();
                let nl = 0;
                let nr = 0;
                for (let b = 0; b < cut; ++b) {
                    if (counts[b]) grow(left, bins[b]!);
                    nl += counts[b]!;
                }
                for (let b = cut; b < BINS; ++b) {
                    if (counts[b]) grow(right, bins[b]!);
                    nr += counts[b]!;
                }
                if (nl === 0 || nr === 0) continue;
                const cost = f32(f32(area(left) * nl) + f32(area(right) * nr));
                if (cost < bestCost) {
                    bestCost = cost;
                    bestAxis = axis;
                    bestBin = cut;
                }
            }
        }
        if (bestAxis < 0) return n <= this.maxLeaf ? -1 : begin + Math.trunc(n / 2); // all centres equal
        // Cost of a leaf vs. of traversing two children (box test ~ 1 object test).
        if (n <= this.maxLeaf && f32(area(box) * n) <= f32(area(box) + bestCost)) return -1;
        return this.partition(begin, end, (item) => this.binOf(item, bestAxis, centreBox) < bestBin);
    }

    // libstdc++'s std::partition (bidirectional): not stable, and the order
    // it leaves is part of the tree, so the very same swaps.
    partition(first: number, last: number, pred: (item: number) => boolean): number {
        const o = this.order;
        for (;;) {
            for (;;) {
                if (first === last) return first;
                if (pred(o[first]!)) ++first;
                else break;
            }
            --last;
            for (;;) {
                if (first === last) return first;
                if (!pred(o[last]!)) --last;
                else break;
            }
            [o[first], o[last]] = [o[last]!, o[first]!];
            ++first;
        }
    }

    build(nodeIndex: number, begin: number, end: number, level: number): void {
        this.depth = Math.max(this.depth, level);
        if (level > BVH_MAX_DEPTH) throw new Error(`BVH deeper than ${BVH_MAX_DEPTH} levels: degenerate scene?`);
        const box = this.boundsOf(begin, end);
        const node = this.nodes[nodeIndex]!;
        node.box = box;
        const mid = end - begin <= 1 ? -1 : this.split(begin, end, box);
        if (mid < 0) {
            node.first = begin;
            node.count = end - begin;
            return;
        }
        const left = this.nodes.length;
        this.nodes.push({ box: emptyBox(), first: 0, count: 0 }, { box: emptyBox(), first: 0, count: 0 });
        node.first = left;
        node.count = 0;
        this.build(left, begin, mid, level + 1);
        this.build(left + 1, mid, end, level + 1);
    }
}

// The hierarchy of SCENE's spheres, at most MAXLEAF spheres a leaf.
export function buildBvh(scene: Scene, maxLeaf = 2): Bvh {
    if (scene.spheres.length === 0) return { nodes: [], items: [], depth: 0 };
    const b = new Builder(Math.max(1, maxLeaf));
    scene.spheres.forEach((_, i) => {
        b.boxes.push(sphereBounds(scene, i));
        b.centres.push(centre(b.boxes[i]!));
        b.order.push(i);
    });
    b.nodes.push({ box: emptyBox(), first: 0, count: 0 });
    b.build(0, 0, b.order.length, 1);
    return { nodes: b.nodes, items: b.order, depth: b.depth };
}

export interface BvhTexture<T> {
    width: number;
    height: number;
    data: T; // row 0 first (texelFetch's y = 0), as texImage2D takes it
}

// Width and height for COUNT texels (see the top of this file).
function shape(count: number): { width: number; height: number } {
    const width = Math.min(BVH_TEXTURE_WIDTH, count);
    return { width, height: Math.ceil(count / width) };
}

export function packBvhTextures(bvh: Bvh): { nodes: BvhTexture<Float32Array>; items: BvhTexture<Int32Array> } {
    const nodeTexels = Math.max(1, bvh.nodes.length) * 2;
    const n = shape(nodeTexels);
    const nodes = new Float32Array(n.width * n.height * 4);
    bvh.nodes.forEach((node, i) => {
        nodes.set([...node.box.lo, node.first, ...node.box.hi, BVH_LEAF_KINDS * node.count], 8 * i);
    });
    const itemList = bvh.items.length ? bvh.items : [-1];
    const m = shape(itemList.length);
    const items = new Int32Array(m.width * m.height);
    items.set(itemList);
    return { nodes: { ...n, data: nodes }, items: { ...m, data: items } };
}
