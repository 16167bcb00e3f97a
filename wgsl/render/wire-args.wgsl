// The wireframe's indirect draw: six line vertices per triangle of whatever the tessellator
// last built. One thread; it runs on the GPU because only the GPU knows the index count.

// drawArgs and wireArgs (group 0): src/gpu/contract/render.ts WIRE_ARGS_GROUP, prepended.

// One thread on purpose: a single indirect record to derive, no work to spread.
@compute @workgroup_size(1)
fn wireArgsMain() {
  // drawIndirect layout: vertexCount, instanceCount, firstVertex, firstInstance.
  wireArgs[0] = (drawArgs[0] / 3u) * 6u;
  wireArgs[1] = drawArgs[1];
  wireArgs[2] = 0u;
  wireArgs[3] = 0u;
}
