// The page refuses a scene with more spheres than the browser's uniform
// blocks hold (sphere_block.ts), in one line naming the limit: WebGL 2
// guarantees only 16 KB blocks, 1024 spheres.
import assert from 'node:assert/strict';
import { test } from 'node:test';

import { SceneLimitError } from '../../dist/raytrace/scene_limit_error.js';
import { checkSpheresFitBlock } from '../../dist/raytrace/sphere_block.js';

const withSpheres = (n) => ({ spheres: Array.from({ length: n }, () => ({ center: [0, 0, 0], radius: 1 })) });

test('1024 spheres fit a 16 KB block, 1025 are refused in one line naming the limit', () => {
  assert.doesNotThrow(() => checkSpheresFitBlock(withSpheres(1024), 16384, 'big.json'));
  assert.throws(() => checkSpheresFitBlock(withSpheres(1025), 16384, 'big.json'), (e) => {
    assert.ok(e instanceof SceneLimitError);
    assert.equal(e.message, 'big.json: spheres: 1025 spheres, but this browser\'s uniform blocks hold at most 1024 ' +
      '(MAX_UNIFORM_BLOCK_SIZE 16384 bytes, 16 per sphere)');
    return true;
  });
  assert.doesNotThrow(() => checkSpheresFitBlock(withSpheres(4096), 65536, 'big.json'));
});
