#pragma once
// Pak's library in one include: the packers (RepulsionPak, FLOWPAK, AnimationPak) and the
// evenness metrics, with the scene and art types they take. Reading and writing files is in
// pak/io/; docs/architecture.md shows the layers.
#include "pak/animation/animation.hpp"
#include "pak/error.hpp"
#include "pak/flow/flow.hpp"
#include "pak/geom/art.hpp"
#include "pak/geom/scene.hpp"
#include "pak/metrics/metrics.hpp"
#include "pak/repulsion/repulsion.hpp"
#include "pak/sim/packing.hpp"
