// Vertices at exactly one position get one id, numbered in order of first
// appearance: the native code keys a std::map by the float tuple (x, y, z),
// where -0 and +0 are one position. Here an open-addressing hash table over
// the float bits does it, much faster than a Map with string keys (a mesh
// can have a million vertices).

export interface PositionIds {
    ids: Uint32Array; // per vertex
    count: number; // distinct positions
}

// MurmurHash3's finaliser: every input bit moves every output bit (float
// bits of round numbers have all their low bits zero).
export function mix(h: number): number {
    h = Math.imul(h ^ (h >>> 16), 0x85ebca6b);
    h = Math.imul(h ^ (h >>> 13), 0xc2b2ae35);
    return (h ^ (h >>> 16)) >>> 0;
}

export function positionIds(positions: Float32Array): PositionIds {
    const n = Math.floor(positions.length / 3);
    // The bits of each coordinate, with -0 read as +0.
    const bits = new Uint32Array(new Float32Array(positions.subarray(0, 3 * n)).buffer);
    for (let k = 0; k < bits.length; ++k) if (bits[k] === 0x80000000) bits[k] = 0;
    let size = 1;
    while (size < 2 * n) size *= 2;
    const table = new Int32Array(size).fill(-1); // a vertex of each position
    const ids = new Uint32Array(n);
    let count = 0;
    for (let i = 0; i < n; ++i) {
        const x = bits[3 * i]!;
        const y = bits[3 * i + 1]!;
        const z = bits[3 * i + 2]!;
        for (let slot = mix(mix(mix(x) ^ y) ^ z) & (size - 1); ; slot = (slot + 1) & (size - 1)) {
            const j = table[slot]!;
            if (j < 0) {
                table[slot] = i;
                ids[i] = count++;
                break;
            }
            if (bits[3 * j] === x && bits[3 * j + 1] === y && bits[3 * j + 2] === z) {
                ids[i] = ids[j]!;
                break;
            }
        }
    }
    return { ids, count };
}
