// The switches of a frame (native: framework/src/course/render_settings.h)
// and the keys that change them in the window (app/settings_keys.cpp).
export const COLOR_MODES = ['RGB', 'BRB', 'BRR', 'RBB', 'GGR'];
export const MAX_DEPTH = 8;

export const FUR_TECHNIQUES = ['shells_and_fins', 'fur_shader'];
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
}

export const defaultSettings = (): RenderSettings => ({
  shadows: true, maxDepth: MAX_DEPTH, glow: true, normalMaps: true, colorMode: 0,
  shells: 0, furLength: 1, fins: true, furTechnique: 0,
});

const FUR_LENGTH_STEP = 1.25, MIN_FUR_LENGTH = 0.25, MAX_FUR_LENGTH = 4;

// The fur track's keys: [ ] shells, - = fur length, F fins, T technique.
// SCENESHELLS: what shells 0 means, so that [ and ] start from it.
export function applyFurKey(s: RenderSettings, key: string, sceneShells: number): string | null {
  const onOff = (b: boolean) => (b ? 'on' : 'off');
  switch (key) {
    case '[': case ']':
      s.shells = Math.min(MAX_SHELLS, Math.max(1, (s.shells || sceneShells) + (key === ']' ? 1 : -1)));
      return `shells ${s.shells}`;
    case '-': case '=':
      s.furLength = Math.min(MAX_FUR_LENGTH, Math.max(MIN_FUR_LENGTH, key === '=' ? s.furLength * FUR_LENGTH_STEP : s.furLength / FUR_LENGTH_STEP));
      return `fur length x${s.furLength.toPrecision(3)}`;
    case 'f': case 'F': s.fins = !s.fins; return `fins ${onOff(s.fins)}`;
    case 't': case 'T':
      s.furTechnique = (s.furTechnique + 1) % FUR_TECHNIQUES.length;
      return `technique ${FUR_TECHNIQUES[s.furTechnique]}`;
    default: return null;
  }
}

// The native window's keys: 1 shadows, G glow, N normal maps, Left/Right
// depth, Up/Down colour mode. Returns what changed, or null for another key.
export function applySettingsKey(s: RenderSettings, key: string): string | null {
  const onOff = (b: boolean) => (b ? 'on' : 'off');
  switch (key) {
    case '1': s.shadows = !s.shadows; return `shadows ${onOff(s.shadows)}`;
    case 'g': case 'G': s.glow = !s.glow; return `glow ${onOff(s.glow)}`;
    case 'n': case 'N': s.normalMaps = !s.normalMaps; return `normal maps ${onOff(s.normalMaps)}`;
    case 'ArrowRight': case 'ArrowLeft':
      s.maxDepth = Math.min(MAX_DEPTH, Math.max(1, s.maxDepth + (key === 'ArrowRight' ? 1 : -1)));
      return `max depth ${s.maxDepth}`;
    case 'ArrowUp': case 'ArrowDown':
      s.colorMode = (s.colorMode + (key === 'ArrowUp' ? 1 : COLOR_MODES.length - 1)) % COLOR_MODES.length;
      return `colour mode ${COLOR_MODES[s.colorMode]}`;
    default: return null;
  }
}
