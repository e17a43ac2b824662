// The native window's keys for the switches (native: app/settings_keys.cpp),
// each only on the stages that have what it switches (stage.json's
// features), and the overlay's rows for the same switches.
import type { StageJson } from '../course/catalog.js';
import { COLOR_MODES, FUR_MESHES, FUR_TECHNIQUES, MAX_DEPTH, MAX_SHELLS, type RenderSettings } from '../raytrace/render_settings.js';

const FUR_LENGTH_STEP = 1.25, MIN_FUR_LENGTH = 0.25, MAX_FUR_LENGTH = 4;
const onOff = (b: boolean) => (b ? 'on' : 'off');

interface Switch {
  feature: string;  // the stage.json feature the switch needs
  keys: string[];
  apply(s: RenderSettings, key: string, sceneShells: number): string;
  row(s: RenderSettings, sceneShells: number): string;
}

const SWITCHES: Switch[] = [
  { feature: 'shadows', keys: ['1'], apply: (s) => `shadows ${onOff((s.shadows = !s.shadows))}`, row: (s) => `shadows ${onOff(s.shadows)}` },
  {
    feature: 'recursion', keys: ['ArrowLeft', 'ArrowRight'],
    apply: (s, k) => `max depth ${(s.maxDepth = Math.min(MAX_DEPTH, Math.max(1, s.maxDepth + (k === 'ArrowRight' ? 1 : -1))))}`,
    row: (s) => `depth ${s.maxDepth}`,
  },
  { feature: 'textures', keys: ['g', 'G'], apply: (s) => `glow ${onOff((s.glow = !s.glow))}`, row: (s) => `glow ${onOff(s.glow)}` },
  { feature: 'normal_maps', keys: ['n', 'N'], apply: (s) => `normal maps ${onOff((s.normalMaps = !s.normalMaps))}`, row: (s) => `normal maps ${onOff(s.normalMaps)}` },
  {
    feature: 'color_modes', keys: ['ArrowUp', 'ArrowDown'],
    apply: (s, k) => `colour mode ${COLOR_MODES[(s.colorMode = (s.colorMode + (k === 'ArrowUp' ? 1 : COLOR_MODES.length - 1)) % COLOR_MODES.length)]}`,
    row: (s) => `colour ${COLOR_MODES[s.colorMode]}`,
  },
  {
    feature: 'shells', keys: ['[', ']'],
    apply: (s, k, scene) => `shells ${(s.shells = Math.min(MAX_SHELLS, Math.max(1, (s.shells || scene) + (k === ']' ? 1 : -1))))}`,
    row: (s, scene) => `shells ${s.shells || scene}`,
  },
  {
    feature: 'shells', keys: ['-', '='],
    apply: (s, k) => {
      s.furLength = Math.min(MAX_FUR_LENGTH, Math.max(MIN_FUR_LENGTH, k === '=' ? s.furLength * FUR_LENGTH_STEP : s.furLength / FUR_LENGTH_STEP));
      return `fur length x${s.furLength.toPrecision(3)}`;
    },
    row: (s) => `length x${s.furLength.toPrecision(3)}`,
  },
  { feature: 'fins', keys: ['f', 'F'], apply: (s) => `fins ${onOff((s.fins = !s.fins))}`, row: (s) => `fins ${onOff(s.fins)}` },
  {
    feature: 'fur_shader', keys: ['t', 'T'],
    apply: (s) => `technique ${FUR_TECHNIQUES[(s.furTechnique = (s.furTechnique + 1) % FUR_TECHNIQUES.length)]}`,
    row: (s) => `technique ${FUR_TECHNIQUES[s.furTechnique]}`,
  },
  {
    feature: 'mesh', keys: ['m', 'M'],
    apply: (s) => `mesh ${meshName((s.furMesh = (s.furMesh + 1) % (FUR_MESHES.length + 1)))}`,
    row: (s) => `mesh ${meshName(s.furMesh)}`,
  },
];

function meshName(furMesh: number): string {
  return furMesh > 0 ? FUR_MESHES[furMesh - 1]! : "the scene's";
}

const has = (stage: StageJson, f: string) => stage.features.includes(f);

// What KEY changed, or null when it switches nothing on STAGE.
export function applySettingsKey(stage: StageJson, s: RenderSettings, key: string, sceneShells: number): string | null {
  const sw = SWITCHES.find((x) => x.keys.includes(key) && has(stage, x.feature));
  return sw ? sw.apply(s, key, sceneShells) : null;
}

// The switches STAGE has, as overlay text, two or three to a line.
export function settingsRows(stage: StageJson, s: RenderSettings, sceneShells: number): string[] {
  const items = SWITCHES.filter((x) => has(stage, x.feature)).map((x) => x.row(s, sceneShells));
  const rows: string[] = [];
  for (let i = 0; i < items.length; i += 3) rows.push(items.slice(i, i + 3).join('  '));
  return rows;
}
