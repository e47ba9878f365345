#pragma once
// A discrete medial axis of a raster region, robust to the raster's staircase. Not installed.
#include <cstdint>
#include <vector>

namespace pak::metrics_internal {

// Where the medial axis crosses the segment between two 4-neighbour cells of the region.
struct AxisCrossing {
  double radius = 0.0;  // of the largest empty disc centred on the crossing, in cells
  double weight = 0.0;  // length of medial axis the crossing stands for, in cells
  int cell = 0;         // the one of the two cells the axis passes nearer to
};

// The region is the cells where `inside` is set on the n × n grid; `nearest` holds each
// cell's nearest cell outside it (nearestOccupiedCells of the complement). Two neighbours
// p, q of the region straddle the medial axis when their nearest outside cells a, b differ:
// the axis is the bisector of a and b, crossed between p and q. The crossing counts when
//   - a and b are at least 3 cells apart: nearer ones are the staircase of one boundary, and
//   - a and b surely subtend at least 105° seen from the crossing x (the angle less
//     2 atan(0.5 / |x - a|), since a and b are cell centres, each about half a cell from the
//     boundary point it stands for): the disc there touches the boundary on two roughly
//     opposite sides. That keeps channels (180°), tapering wedges sharper than 75° and the
//     three-way junctions between channels (120° at the centre of a symmetric one), and drops
//     the branches into right-angle and blunter corners (90° and less), which the thesis finds
//     misrepresent negative space (Fig. 6.8), and those raster noise grows along a smooth
//     boundary (their angle shrinks like sqrt(2 / distance)). 105° lies midway between the
//     right angle and the three-way junction.
// The limit of 3 cells and the allowance are raster-noise filters, which fade as the grid gets
// finer; the angle itself is scale-free.
// Each crossing is weighted by |cos| of the angle between b - a (the axis normal) and p → q:
// rows are crossed |t_y| times per unit length of an axis with unit tangent t, columns |t_x|
// times, so the weights sum to the axis length whatever its direction.
std::vector<AxisCrossing> medialAxisCrossings(const std::vector<std::uint8_t>& inside,
                                              const std::vector<int>& nearest, int n);

}  // namespace pak::metrics_internal
