// The one place both tools (osd_eval, osd_time) hand a parsed OBJ (obj_reader.h) to OpenSubdiv:
// its faces, crease and corner tags and holes as a Far::TopologyDescriptor, refined under `sdc`.
#pragma once
#include <opensubdiv/far/topologyDescriptor.h>
#include <opensubdiv/far/topologyRefinerFactory.h>

#include <memory>

#include "obj_reader.h"

static std::unique_ptr<OpenSubdiv::Far::TopologyRefiner> createRefiner(const Obj &o, const OpenSubdiv::Sdc::Options &sdc) {
  using namespace OpenSubdiv;
  Far::TopologyDescriptor d;
  d.numVertices = (int)o.pos.size() / 3;
  d.numFaces = (int)o.counts.size();
  d.numVertsPerFace = o.counts.data();
  d.vertIndicesPerFace = o.indices.data();
  d.numCreases = (int)o.creaseW.size();
  d.creaseVertexIndexPairs = o.creasePairs.data();
  d.creaseWeights = o.creaseW.data();
  d.numCorners = (int)o.cornerW.size();
  d.cornerVertexIndices = o.cornerV.data();
  d.cornerWeights = o.cornerW.data();
  d.numHoles = (int)o.holes.size();
  d.holeIndices = o.holes.data();
  using Factory = Far::TopologyRefinerFactory<Far::TopologyDescriptor>;
  return std::unique_ptr<Far::TopologyRefiner>(Factory::Create(d, Factory::Options(Sdc::SCHEME_CATMARK, sdc)));
}
