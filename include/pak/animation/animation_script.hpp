#pragma once
// What an AnimationPak run animates (thesis 5.3–5.4), as read from the animation file (JSON;
// see docs/animation-format.md): per element, transform tracks, handle trajectories for the
// as-rigid-as-possible shape animation, guided targets, loops and a preferred orientation.
#include <optional>
#include <string>
#include <vector>

#include "pak/animation/keyframes.hpp"
#include "pak/geom/vec2.hpp"

namespace pak {

// The in-place animation of one element (thesis 5.3.2): shape first (handles), then the
// transform about the element's centre. Units are the element file's own.
struct ElementAnimation {
  std::vector<ScalarKey> rotation;   // degrees, counter-clockwise in a y-up frame; none: 0
  std::vector<ScalarKey> scale;      // factor; none: 1
  std::vector<PointKey> translation; // element units; none: (0, 0)
  struct HandleTrack {
    std::string name;                // matches an ElementHandle of the element's SVG
    std::vector<PointKey> offset;    // displacement from the handle's rest position
  };
  std::vector<HandleTrack> handles;
};

// A spacetime target of a guided element (thesis 5.4): its anchor passes near (x, y) at t.
// Positions are in the container file's coordinates.
struct GuideTarget {
  double t = 0.0;
  Vec2 position;
  std::optional<double> scale;     // element scale at the target (factor of its packed size)
  std::optional<double> rotation;  // degrees
};

struct AnimatedElementSpec {
  std::string id;          // unique name, used by `loopTo`; default: "element-<index>"
  std::string svg;         // element file, resolved against the animation file's folder
  int count = 1;           // copies to seed (guided elements: exactly one)
  ElementAnimation animation;
  std::vector<GuideTarget> targets;  // non-empty: a guided element (t₁ = 0, tₙ = 1)
  // Its t = 1 slice joins the t = 0 slice of the element with this id (a permutation loop,
  // Figure 5.11d); empty: its own t = 0 slice. Only for guided elements (count 1).
  std::string loopTo;
  // Guided elements only: it may leave the container (thesis Fig. 5.17). Its slices feel no
  // boundary force, and what lies outside takes no container space: the frame checks count
  // only its part inside.
  bool leavesContainer = false;
  // Preferred orientation in degrees (torsional force); nullopt: random orientation, no torsion.
  std::optional<double> orientation;
  // "orientation": "field": each copy faces the direction of the container's vector field
  // (FLOWPAK's, from the `guides` strokes) at its seed, and torsion keeps it so (Fig. 5.18).
  bool orientationFromField = false;
};

struct AnimationScript {
  std::string source;       // the file it was read from, for error messages
  std::vector<AnimatedElementSpec> elements;
  bool loop = true;         // t = 1 joins t = 0 (thesis 5.5.2, constraint 3)
  int slices = 100;         // n_s
  int frames = 500;         // rendered frames
  double duration = 10.0;   // seconds one loop lasts in the GIF / animated SVG / video
};

}  // namespace pak
