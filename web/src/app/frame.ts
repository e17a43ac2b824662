// What one picture needs besides the stage: a camera, a time and the
// switches - from the scene's own camera or from one of the stage's check
// views (native: CheckView in stage_catalog.h).
import { Camera, type CameraPose } from './camera.js';
import type { CheckViewJson, StageJson } from '../course/catalog.js';
import { COLOR_MODES, defaultSettings, FUR_TECHNIQUES, type RenderSettings } from '../raytrace/render_settings.js';

export interface Frame {
  camera: Camera;
  time: number;
  settings: RenderSettings;
}

export function sceneOfView(stage: StageJson, view?: CheckViewJson): string {
  return view?.scene ?? stage.scene;
}

// STAGE: its "technique" is the fur technique shown unless the view says
// otherwise (f4: the fur shader), as natively.
export function frameOfView(scenePose: CameraPose, fovYDeg: number, view?: CheckViewJson, stage?: StageJson): Frame {
  const settings = defaultSettings();
  if (stage?.technique) settings.furTechnique = Math.max(0, FUR_TECHNIQUES.indexOf(stage.technique));
  let pose = scenePose;
  if (view) {
    if (view.camera) pose = { position: view.camera.position, yawDeg: view.camera.yaw, pitchDeg: view.camera.pitch };
    settings.shadows = view.shadows ?? true;
    settings.maxDepth = view.max_depth ?? settings.maxDepth;
    settings.glow = view.glow ?? true;
    settings.normalMaps = view.normal_maps ?? true;
    if (view.color_mode) settings.colorMode = Math.max(0, COLOR_MODES.indexOf(view.color_mode));
    settings.shells = view.shells ?? 0;
    settings.fins = view.fins ?? true;
    if (view.technique) settings.furTechnique = Math.max(0, FUR_TECHNIQUES.indexOf(view.technique));
  }
  return { camera: new Camera(pose, fovYDeg), time: view?.time ?? 0, settings };
}
