// Reading the statements of a Wavefront OBJ file that make a mesh: v, vt, vn
// and f (corners v, v/vt, v//vn, v/vt/vn; negative indices count back from
// the last element read so far). The native build reads OBJ files with
// tinyobjloader, which turns most mistakes into zeros or skips them; this
// reader gives the same numbers for a well-formed file and fails on any
// mistake with one line, "FILE:LINE: what".
//
// Statements that do not change the mesh (o, g, s, usemtl, mtllib, l, p,
// free-form geometry, ...) are ignored, as natively; an unknown statement is
// an error (natively ignored), so that a typo does not drop data silently.
import { MeshError } from './mesh.js';
import { parseObjNumber } from './obj_number.js';

export class ObjError extends MeshError {
    constructor(message: string) {
        super(message);
        this.name = 'ObjError';
    }
}

// One corner of a face: 0-based indices, -1 where the corner names none.
export interface ObjCorner {
    v: number;
    vt: number;
    vn: number;
}

export interface ObjFace {
    corners: ObjCorner[];
    line: number; // 1-based, for messages
}

export interface ObjData {
    vertices: number[]; // x, y, z per v line, as floats
    texcoords: number[]; // u, v per vt line
    normals: number[]; // x, y, z per vn line
    faces: ObjFace[];
}

const IGNORED = new Set([
    'o', 'g', 's', 'usemtl', 'mtllib', 'l', 'p', 'vp', 'vw', 't',
    'cstype', 'deg', 'bmat', 'step', 'curv', 'curv2', 'surf', 'parm', 'trim', 'hole', 'scrv', 'sp', 'end',
    'con', 'mg', 'bevel', 'c_interp', 'd_interp', 'lod', 'usemap', 'maplib', 'shadow_obj', 'trace_obj',
    'ctech', 'stech', 'call', 'csh',
]);

const INDEX = /^[+-]?\d+$/;

class LineReader {
    constructor(
        readonly file: string,
        readonly line: number,
    ) {}

    fail(what: string): never {
        throw new ObjError(`${this.file}:${this.line}: ${what}`);
    }

    // Between LEAST and MOST numbers; each must be finite as a float.
    numbers(args: string[], least: number, most: number, form: string): number[] {
        if (args.length < least || args.length > most) this.fail(`expected "${form}"`);
        return args.map((a) => {
            const x = parseObjNumber(a);
            if (x === null) this.fail(`"${a}" is not a number`);
            if (!Number.isFinite(x)) this.fail(`${a} is not a finite number (as a float)`);
            return x;
        });
    }

    // An index into COUNT elements read so far, made 0-based; a forward
    // reference is checked once the whole file is read (obj_mesh.ts).
    index(text: string, count: number, what: string): number {
        if (!INDEX.test(text)) this.fail(`"${text}" is not a ${what} index`);
        const i = Number(text);
        if (i === 0) this.fail(`${what} index 0 (OBJ counts from 1)`);
        if (Math.abs(i) > 2147483647) this.fail(`${what} index ${text} is out of range`);
        if (i > 0) return i - 1;
        if (count + i < 0) this.fail(`relative ${what} index ${i} counts back past the first ${what}`);
        return count + i;
    }

    corner(text: string, data: ObjData): ObjCorner {
        const parts = text.split('/');
        if (parts.length > 3 || parts[0] === '' || (parts.length === 2 && parts[1] === '') || (parts.length === 3 && parts[2] === ''))
            this.fail(`"${text}" is not a face corner (v, v/vt, v//vn or v/vt/vn)`);
        const v = this.index(parts[0]!, data.vertices.length / 3, 'vertex');
        const vt = parts.length >= 2 && parts[1] !== '' ? this.index(parts[1]!, data.texcoords.length / 2, 'texture coordinate') : -1;
        const vn = parts.length === 3 ? this.index(parts[2]!, data.normals.length / 3, 'normal') : -1;
        return { v, vt, vn };
    }
}

// The v, vt, vn and f statements of TEXT, named FILE in messages.
export function readObj(text: string, file: string): ObjData {
    const data: ObjData = { vertices: [], texcoords: [], normals: [], faces: [] };
    // Lines end at \n, \r\n or a lone \r, as tinyobjloader's safeGetline.
    const lines = text.split(/\r\n|\r|\n/);
    lines.forEach((raw, i) => {
        const tokens = raw.split(/[ \t]+/).filter((t) => t !== '');
        // A comment runs to the end of the line, also after a statement.
        const comment = tokens.findIndex((t) => t.startsWith('#'));
        if (comment >= 0) tokens.length = comment;
        const keyword = tokens[0];
        if (keyword === undefined) return;
        const r = new LineReader(file, i + 1);
        const args = tokens.slice(1);
        switch (keyword) {
            case 'v': // x y z, then an optional w or r g b (ignored)
                data.vertices.push(...r.numbers(args, 3, 7, 'v x y z').slice(0, 3));
                break;
            case 'vt': // u [v [w]]: v defaults to 0, w is ignored
                data.texcoords.push(...[...r.numbers(args, 1, 3, 'vt u v'), 0].slice(0, 2));
                break;
            case 'vn':
                data.normals.push(...r.numbers(args, 3, 3, 'vn x y z'));
                break;
            case 'f': {
                const corners = args.map((a) => r.corner(a, data));
                if (corners.length < 3) r.fail('a face needs at least 3 corners');
                data.faces.push({ corners, line: i + 1 });
                break;
            }
            default:
                if (!IGNORED.has(keyword)) r.fail(`unknown statement "${keyword}"`);
        }
    });
    return data;
}
