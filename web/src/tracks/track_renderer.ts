// What the page, the tests and the benchmark need from a track's renderer
// (native: course/track_renderer.h): draw a frame into the canvas, the open
// TODOs of the student's files, and letting go of the GPU objects.
import type { Camera } from '../app/camera.js';
import type { RenderSettings } from '../raytrace/render_settings.js';
import type { OpenTodo } from '../core/core.js';

export interface TrackRenderer {
  readonly todos: OpenTodo[];
  render(camera: Camera, timeSeconds: number, settings: RenderSettings, width: number, height: number): void;
  dispose(): void;
}
