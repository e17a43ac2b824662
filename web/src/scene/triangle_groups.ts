// The scene's triangles in groups, exactly as the native build forms them
// (framework/src/raytrace/scene/triangle_groups.cpp): runs of consecutive
// triangles of one material, at most TRIANGLE_GROUP_MAX long, each with the
// smallest and largest coordinates of its corners (exact: min and max only
// pick values, they round nothing). Stage 08 skips a group whose box a ray
// misses (solution/08-full/find_closest.glsl).
import { Scene, Vec3 } from './scene.js';

export const TRIANGLE_GROUP_MAX = 12; // triangle_groups.h's kTriangleGroupMax

export interface TriangleGroup {
    first: number;
    count: number;
    lo: Vec3;
    hi: Vec3;
}

export function triangleGroups(scene: Scene): TriangleGroup[] {
    const groups: TriangleGroup[] = [];
    scene.triangles.forEach((t, i) => {
        const last = groups[groups.length - 1];
        const joins = last !== undefined && last.count < TRIANGLE_GROUP_MAX && scene.triangles[i - 1]!.material === t.material;
        const g: TriangleGroup = joins ? last : { first: i, count: 0, lo: [...t.vertices[0]], hi: [...t.vertices[0]] };
        if (!joins) groups.push(g);
        g.count += 1;
        for (const p of t.vertices)
            for (let k = 0; k < 3; ++k) {
                g.lo[k] = Math.min(g.lo[k]!, p[k]!);
                g.hi[k] = Math.max(g.hi[k]!, p[k]!);
            }
    });
    return groups;
}
