// Reading values out of a scene file's JSON with one-line messages that name
// the file and the JSON path, word for word as the native build
// (framework/src/core/json_reader.cpp): "assets/scenes/lite.json:
// spheres[3].radius: expected a positive number".
import { divide, f32, length } from './float32.js';
import { isObject, Json, JsonNumber, JsonObject, JsonParseError, objectKeys, parseJson } from './json_parse.js';
import { CameraPose, DEFAULT_FOV_Y_DEG, Vec3 } from './scene.js';

// Any problem with a scene file: "FILE: where: what".
export class SceneError extends Error {
    constructor(message: string) {
        super(message);
        this.name = 'SceneError';
    }
}

// The document in TEXT, shown as SHOWN in messages (json_reader.cpp's
// parseJsonFile): "SHOWN: line 3, column 7: JSON syntax error" (the line and
// column where the browser's parser stopped, which can differ from the
// native parser's by a few characters).
export function parseJsonText(text: string, shown: string): Json {
    try {
        return parseJson(text);
    } catch (e) {
        if (!(e instanceof JsonParseError)) throw e;
        if (e.kind === 'range')
            throw new SceneError(`${shown}: JSON number out of range (larger than a double can hold)`);
        throw new SceneError(`${shown}: ${e.message}`);
    }
}

// nlohmann's obj.contains(key): false for anything but an object.
export function has(v: Json | undefined, key: string): boolean {
    return isObject(v) && v.has(key);
}

// OBJ[KEY] where the caller knows it is there (after has()).
export function at(obj: Json, key: string): Json {
    return (obj as JsonObject).get(key)!;
}

export class JsonReader {
    constructor(readonly file: string) {}

    fail(where: string, what: string): never {
        throw new SceneError(`${this.file}: ${where}: ${what}`);
    }

    // OBJ[KEY]; WHERE is OBJ's own path ("camera": 'camera: missing "yaw"').
    member(obj: Json, where: string, key: string): Json {
        if (!isObject(obj)) this.fail(where, 'expected an object');
        if (!obj.has(key)) this.fail(where, `missing "${key}"`);
        return obj.get(key)!;
    }

    // A finite number within +-1e30, as a float.
    number(v: Json, where: string): number {
        if (!(v instanceof JsonNumber)) this.fail(where, 'expected a number');
        const d = v.value;
        if (!Number.isFinite(d) || Math.abs(d) > 1e30) this.fail(where, 'number out of range');
        return f32(d);
    }

    string(v: Json, where: string): string {
        if (typeof v !== 'string') this.fail(where, 'expected a string');
        return v;
    }

    // Fails on a key that is not in KNOWN (or "comment"); the first such key
    // in sorted order, as the native reader walks a std::map.
    allowOnly(obj: Json, where: string, known: string[]): void {
        if (!isObject(obj)) return; // member() says "expected an object" where it matters
        for (const key of objectKeys(obj)) {
            if (key === 'comment' || known.includes(key)) continue;
            this.fail(where === '' ? key : `${where}.${key}`, `unknown key (known here: ${known.join(', ')})`);
        }
    }

    // The list under KEY, or an empty list when the file has none.
    optionalList(doc: Json, key: string): Json[] {
        if (!has(doc, key)) return [];
        const list = at(doc, key);
        if (!Array.isArray(list)) this.fail(key, 'expected a list');
        return list;
    }

    positive(v: Json, where: string): number {
        const f = this.number(v, where);
        if (!(f > 0)) this.fail(where, 'expected a positive number');
        return f;
    }

    vec3(v: Json, where: string): Vec3 {
        if (!Array.isArray(v) || v.length !== 3) this.fail(where, 'expected [x, y, z]');
        return [this.number(v[0]!, `${where}[0]`), this.number(v[1]!, `${where}[1]`), this.number(v[2]!, `${where}[2]`)];
    }

    // Normalised; not zero.
    direction(v: Json, where: string): Vec3 {
        const d = this.vec3(v, where);
        const len = length(d);
        if (!(len > f32(1e-6)) || !Number.isFinite(len)) this.fail(where, 'expected a direction, not a zero vector');
        return divide(d, len);
    }

    // Components in [0, 1].
    color(v: Json, where: string): Vec3 {
        const c = this.vec3(v, where);
        for (const x of c) if (x < 0 || x > 1) this.fail(where, 'colour components must lie in [0, 1]');
        return c;
    }
}

export interface SceneCamera {
    pose: CameraPose;
    fovYDeg: number;
}

// The "camera" block: {"position": [x, y, z], "yaw": deg, "pitch": deg,
// "fov_y": deg (optional, below 170)}.
export function readSceneCamera(r: JsonReader, doc: Json): SceneCamera {
    const cam = r.member(doc, 'scene', 'camera');
    r.allowOnly(cam, 'camera', ['position', 'yaw', 'pitch', 'fov_y']);
    const pose: CameraPose = {
        position: r.vec3(r.member(cam, 'camera', 'position'), 'camera.position'),
        yawDeg: r.number(r.member(cam, 'camera', 'yaw'), 'camera.yaw'),
        pitchDeg: r.number(r.member(cam, 'camera', 'pitch'), 'camera.pitch'),
    };
    let fovYDeg = DEFAULT_FOV_Y_DEG;
    if (has(cam, 'fov_y')) {
        fovYDeg = r.positive(at(cam, 'fov_y'), 'camera.fov_y');
        if (fovYDeg >= 170) r.fail('camera.fov_y', 'must be below 170 degrees');
    }
    return { pose, fovYDeg };
}
