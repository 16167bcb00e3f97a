/**
 * When the demo's builds are stale, in one place: which change needs the tessellated output
 * rebuilt (and the instanced tessellator's level pass run again), and which only a redraw. The
 * demo draws on demand and keeps its builds between frames; it tells this object what changed
 * and asks it, each frame, what to encode (src/app/tessellation-demo.ts onFrame). DOM-free and
 * GPU-free (tests/app/build-staleness.test.ts).
 */

/** What a frame draws, as far as its builds go. */
export interface FrameInputs {
  /** The turntable turns (the camera moves every frame). */
  spin: boolean;
  /** The drawn build depends on the camera (adaptive factors on a tessellated surface). */
  dependsOnCamera: boolean;
  /** Adaptive factors (the instanced tessellator's levels follow the camera then). */
  adaptive: boolean;
  /** The instanced tessellator draws (alone, or the split view's right half). */
  instanced: boolean;
  /** The compute tessellator's output is drawn (alone, or the split view's left half). */
  computeDrawn: boolean;
  /** The drawn geometry has an output to build into. */
  hasOutput: boolean;
}

/** What a frame encodes. */
export interface FramePlan {
  /** The instanced tessellator's level pass (else only the copy of its owed counts). */
  levels: boolean;
  /** The compute tessellator's build of the drawn output. */
  build: boolean;
  /** The builds were stale at this frame: the comparison's right half rebuilds with the left. */
  stale: boolean;
}

export class BuildStaleness {
  #stale = true;

  /** The builds are out of date (nothing built yet, or invalidate since). */
  get stale(): boolean {
    return this.#stale;
  }

  /** The model, surface, factors, displacement or a view that builds changed: rebuild. */
  invalidate(): void {
    this.#stale = true;
  }

  /** The camera moved (or the canvas was resized): a build that depends on the camera is stale;
   * any other needs only a redraw. */
  cameraMoved(dependsOnCamera: boolean): void {
    if (dependsOnCamera) this.#stale = true;
  }

  /** This frame's builds; what they bring up to date is no longer stale. */
  plan(f: FrameInputs): FramePlan {
    // While spinning, adaptive factors follow the moving camera: rebuild every frame.
    if (f.spin && f.dependsOnCamera) this.#stale = true;
    let levels = false;
    if (f.instanced) {
      // The instanced tessellator's levels follow the camera in adaptive mode.
      if (f.spin && f.adaptive) this.#stale = true;
      levels = this.#stale;
      // Alone, its level pass is the build; in the split view the compute build still owes.
      if (levels && !f.computeDrawn) this.#stale = false;
    }
    const stale = this.#stale;
    const build = f.computeDrawn && stale && f.hasOutput;
    if (build) this.#stale = false;
    return { levels, build, stale };
  }
}
