#pragma once
// Sub-region blobs (thesis 3.3.4): an approximate generalized Voronoi partition of the free
// space (containers minus fixed elements) around the streamlines, and the blob operations of
// the refinement (3.3.6).
#include <vector>

#include "pak/flow/vector_field.hpp"
#include "pak/geom/polygon.hpp"

namespace pak {

struct BlobOptions {
  // Grid cells along the longer side of the free space's bounds (the partition is computed
  // on a grid, as the thesis's level-set method [OS88] is).
  int resolution = 512;
};

// blobs[k] is the part of `freeSpace` closer to streamlines[k] than to any other streamline;
// the blobs are disjoint and together cover `freeSpace` (up to the grid's resolution).
std::vector<Region> computeBlobs(const Region& freeSpace, const std::vector<Polyline>& streamlines,
                                 const BlobOptions& options = {});

// The streamline extended at both ends along the field, in steps of `step`, until it would
// leave `blob` (3.3.4). A streamline already touching its blob's boundary is returned as is.
Polyline extendToBlob(const Polyline& streamline, const Region& blob, const VectorField& field,
                      double step);

// The blob offset outward by at most `limit`, but not into `occupied` (the other placed
// elements) nor out of `freeSpace` ("growing blobs", 3.3.6).
Region growBlob(const Region& blob, const Region& occupied, const Region& freeSpace, double limit);

}  // namespace pak
