// Image files named in a scene file, as URLs. The native build resolves them
// against the scene file's folder and checks they exist while loading; a
// browser cannot check synchronously, so parseScene only resolves them and
// the page reports a missing file when it fetches sceneImageUrls(scene).
import type { Scene } from './scene.js';

// PATH relative to the folder of FILEURL, normalised ("a/./b/../c" -> "a/c"),
// like std::filesystem's folder / path then lexically_normal(). FILEURL may
// be absolute ("http://host/assets/scenes/lite.json") or a path
// ("/assets/scenes/lite.json", "assets/scenes/lite.json").
export function resolveAgainst(fileUrl: string, path: string): string {
    if (/^[a-zA-Z][a-zA-Z0-9+.-]*:/.test(fileUrl)) return new URL(path, fileUrl).href;
    const absolute = path.startsWith('/');
    const folder = fileUrl.includes('/') ? fileUrl.slice(0, fileUrl.lastIndexOf('/') + 1) : '';
    const joined = absolute ? path : folder + path;
    const rooted = joined.startsWith('/');
    const parts: string[] = [];
    for (const part of joined.split('/')) {
        if (part === '' || part === '.') continue;
        if (part === '..' && parts.length > 0 && parts[parts.length - 1] !== '..') parts.pop();
        else if (part === '..' && rooted) continue; // nothing above the root
        else parts.push(part);
    }
    const trailing = joined.endsWith('/') && parts.length > 0 ? '/' : '';
    return (rooted ? '/' : '') + parts.join('/') + trailing;
}

// Every image the scene needs: its texture layers in order, then the six
// sky-box faces (+x, -x, +y, -y, +z, -z) if it has a sky box.
export function sceneImageUrls(scene: Scene): string[] {
    return [...scene.textures, ...(scene.skyBox ?? [])];
}
