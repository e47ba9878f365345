#pragma once
// Per-vertex lists packed in one array (compressed sparse rows): what each simulator's force
// pass reads for the springs and the triangles at a vertex. Built once, before the first
// step, by a counting sort over the incidences in the order they are given, so every
// vertex's list keeps that order and the force sums come out the same on every run.
#include <cassert>
#include <cstddef>
#include <span>
#include <vector>

namespace pak {

template <class Entry>
struct VertexAdjacency {
  std::vector<int> start;      // vertex v's entries are [start[v], start[v + 1])
  std::vector<Entry> entries;

  std::span<const Entry> of(std::size_t v) const {
    return {entries.data() + start[v], entries.data() + start[v + 1]};
  }
  std::size_t vertexCount() const { return start.empty() ? 0 : start.size() - 1; }
};

// `incidences(emit)` calls emit(vertex, entry) once per incidence. It is called twice, to
// count and then to fill, and must emit the same sequence both times.
template <class Entry, class Incidences>
VertexAdjacency<Entry> buildVertexAdjacency(std::size_t vertexCount, Incidences&& incidences) {
  VertexAdjacency<Entry> adjacency;
  std::vector<int>& start = adjacency.start;
  start.assign(vertexCount + 1, 0);
  incidences([&](int v, const Entry&) {
    assert(v >= 0 && static_cast<std::size_t>(v) < vertexCount);
    ++start[static_cast<std::size_t>(v) + 1];
  });
  for (std::size_t v = 0; v < vertexCount; ++v) start[v + 1] += start[v];
  std::vector<int> cursor(start.begin(), start.end() - 1);
  adjacency.entries.resize(static_cast<std::size_t>(start[vertexCount]));
  incidences([&](int v, const Entry& entry) { adjacency.entries[static_cast<std::size_t>(cursor[v]++)] = entry; });
  return adjacency;
}

}  // namespace pak
