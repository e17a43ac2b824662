// A mesh and its edge adjacency as text, for checksums against the native
// build's: one line per vertex with the float bits of position, normal and
// uv; the indices; the edge counts and indices. WITHNAME: a first line with
// the mesh's name.
import { createHash } from 'node:crypto';

import { buildEdgeAdjacency } from '../../dist/fur/mesh/adjacency.js';

export function dumpMesh(m, withName = true) {
    const hex = (a) => [...new Uint32Array(Float32Array.from(a).buffer)].map((u) => u.toString(16).padStart(8, '0') + ' ').join('');
    const lines = [...(withName ? [`name ${m.name}`] : []), `V ${m.positions.length / 3} T ${m.indices.length / 3}`];
    for (let i = 0; i < m.positions.length / 3; ++i)
        lines.push(hex(m.positions.subarray(3 * i, 3 * i + 3)) + hex(m.normals.subarray(3 * i, 3 * i + 3)) + hex(m.uvs.subarray(2 * i, 2 * i + 2)));
    lines.push([...m.indices].map((i) => `${i} `).join(''));
    const a = buildEdgeAdjacency(m);
    lines.push(`E ${a.indices.length / 4} ${a.interiorEdges} ${a.boundaryEdges} ${a.nonManifoldEdges} ${a.degenerateTriangles}`);
    lines.push([...a.indices].map((i) => `${i} `).join(''));
    return lines.join('\n') + '\n';
}

export const sha256 = (text) => createHash('sha256').update(text).digest('hex');
