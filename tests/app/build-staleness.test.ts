// The demo's staleness rule (src/app/build-staleness.ts): which change needs a rebuild, which
// only a redraw, and what each kind of frame (compute, instanced, split) encodes.
import { describe, expect, it } from 'vitest';
import { BuildStaleness, type FrameInputs } from '../../src/app/build-staleness.ts';

const compute: FrameInputs = {
  spin: false,
  dependsOnCamera: false,
  adaptive: false,
  instanced: false,
  computeDrawn: true,
  hasOutput: true,
};
const instancedAlone: FrameInputs = { ...compute, instanced: true, computeDrawn: false };
const split: FrameInputs = { ...compute, instanced: true, computeDrawn: true };

describe('the demo builds', () => {
  it('once at first, then only when invalidated', () => {
    const s = new BuildStaleness();
    expect(s.plan(compute)).toEqual({ levels: false, build: true, stale: true });
    expect(s.plan(compute)).toEqual({ levels: false, build: false, stale: false });
    s.invalidate();
    expect(s.plan(compute).build).toBe(true);
    expect(s.stale).toBe(false);
  });

  it('after a camera move only where the build depends on the camera (adaptive); else redraws', () => {
    const s = new BuildStaleness();
    s.plan(compute);
    s.cameraMoved(false);
    expect(s.plan(compute).build).toBe(false);
    s.cameraMoved(true);
    expect(s.plan({ ...compute, dependsOnCamera: true }).build).toBe(true);
  });

  it('every frame while the turntable turns an adaptive build, never a fixed one', () => {
    const s = new BuildStaleness();
    s.plan(compute);
    for (let i = 0; i < 3; i++) expect(s.plan({ ...compute, spin: true, dependsOnCamera: true }).build).toBe(true);
    expect(s.plan({ ...compute, spin: true }).build).toBe(false);
  });

  it('keeps a build owed until there is an output to build into', () => {
    const s = new BuildStaleness();
    expect(s.plan({ ...compute, hasOutput: false })).toEqual({ levels: false, build: false, stale: true });
    expect(s.plan(compute).build).toBe(true);
  });

  it('the instanced tessellator alone: its level pass is the build', () => {
    const s = new BuildStaleness();
    expect(s.plan(instancedAlone)).toEqual({ levels: true, build: false, stale: false });
    expect(s.plan(instancedAlone).levels).toBe(false);
    // Its adaptive levels follow the turning camera, even on a build that does not depend on it.
    expect(s.plan({ ...instancedAlone, spin: true, adaptive: true }).levels).toBe(true);
    expect(s.plan({ ...instancedAlone, spin: true }).levels).toBe(false);
  });

  it('the split view: the level pass and the compute build in the same frame', () => {
    const s = new BuildStaleness();
    expect(s.plan(split)).toEqual({ levels: true, build: true, stale: true });
    expect(s.plan(split)).toEqual({ levels: false, build: false, stale: false });
  });
});
