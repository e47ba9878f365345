#pragma once
// Report fields the packing commands share, so each has one spelling.
#include <vector>

#include <nlohmann/json.hpp>

#include "pak/geom/verify.hpp"
#include "pak/metrics/evenness.hpp"

#include "length_units.hpp"

namespace pak::cli {

// A report's start: the run's parameters, the units its distances are in, and the lengths
// given with a unit as written.
nlohmann::json reportWithParameters(const nlohmann::json& parameters, const char* units, const GivenLengths& given);

// overlap-count, overlap-area, elements-outside, outside-area, self-intersecting-outlines,
// problems.
void reportCheck(nlohmann::json& report, const PackingCheck& check);

// The evenness measure (pak metrics, pak pack --report): P1–P3, h, the widest pocket …
nlohmann::json evennessJson(const Evenness& evenness);

// elements-per-container: how many of `elements` (each with a `container` index) each of the
// `containers` containers holds.
template <class Element>
void reportElementsPerContainer(nlohmann::json& report, const std::vector<Element>& elements, std::size_t containers) {
  std::vector<int> perContainer(containers, 0);
  for (const Element& e : elements)
    if (e.container >= 0 && e.container < static_cast<int>(perContainer.size())) ++perContainer[e.container];
  report["elements-per-container"] = perContainer;
}

}  // namespace pak::cli
