// The switches of a frame (native: framework/src/course/render_settings.h).
export const COLOR_MODES = ['RGB', 'BRB', 'BRR', 'RBB', 'GGR'];
export const MAX_DEPTH = 8;

export const FUR_TECHNIQUES = ['shells_and_fins', 'fur_shader'];
// Key M's procedural meshes after the scene's own (native: mesh_shapes.h's
// shapeNames(); tests/unit/core_fur.test.mjs holds the two equal).
export const FUR_MESHES = ['sphere', 'torus', 'cube'];
export const MAX_SHELLS = 256;

export interface RenderSettings {
  shadows: boolean;
  maxDepth: number;  // rays per path, 1..8
  glow: boolean;
  normalMaps: boolean;
  colorMode: number;  // index into COLOR_MODES
  // The fur track.
  shells: number;  // shell draws, the skin included; 0: the scene's
  furLength: number;  // a factor on the scene's fur length
  fins: boolean;
  furTechnique: number;  // index into FUR_TECHNIQUES
  furMesh: number;  // 0: the scene's mesh, i: FUR_MESHES[i - 1]
}

export const defaultSettings = (): RenderSettings => ({
  shadows: true, maxDepth: MAX_DEPTH, glow: true, normalMaps: true, colorMode: 0,
  shells: 0, furLength: 1, fins: true, furTechnique: 0, furMesh: 0,
});
