#pragma once
// Overlays that teach: the learner's trail (where the car has been), the expert's ghost path (a translucent
// ribbon as wide as the car, with arrows in the direction of travel; reversing stretches in another colour)
// and the ghost car (the expert's car, translucent, at a given time of its path).
#include <span>
#include <vector>

#include "engine/parking_view/parking_path.hpp"
#include "engine/render/renderer2d.hpp"

namespace sc {

namespace parking_view {
inline constexpr Color kTrail = Color::hex(0xffe28a, 0.85f);
inline constexpr Color kGhostForward = Color::hex(0x5b9bff, 0.30f);
inline constexpr Color kGhostReverse = Color::hex(0xff6f91, 0.30f);
inline constexpr Color kGhostForwardArrow = Color::hex(0xb9d6ff, 0.9f);
inline constexpr Color kGhostReverseArrow = Color::hex(0xffc2cf, 0.9f);
}  // namespace parking_view

// A stretch of a path driven in one direction: sample indices [first, last] (shared with the neighbours).
struct PathRun {
  std::size_t first = 0;
  std::size_t last = 0;
  bool reversing = false;
};

// Splits a path where the car changes between driving forward and reversing. A sample at rest belongs to
// the run it ends; runs shorter than `min_length` metres are merged into the previous one (a car that
// creeps back 2 cm while stopping is not a reversing manoeuvre).
std::vector<PathRun> split_by_direction(const ParkingPath& path, double min_length = 0.3);

struct TrailStyle {
  Color color = parking_view::kTrail;
  float width = 0.25f;  // metres
};
// The polyline of past positions (e.g. the learner's: the car's centre over time).
void paint_trail(Renderer2D& renderer, std::span<const Vec2f> positions, const TrailStyle& style = {});

struct GhostPathStyle {
  float width = 2.0f;          // metres: the car's width, so the ribbon is the swept lane of the car
  float arrow_spacing = 4.0f;  // metres between direction arrows
  Color forward = parking_view::kGhostForward;
  Color reverse = parking_view::kGhostReverse;
  Color forward_arrow = parking_view::kGhostForwardArrow;
  Color reverse_arrow = parking_view::kGhostReverseArrow;
};
void paint_ghost_path(Renderer2D& renderer, const ParkingPath& path, const GhostPathStyle& style = {});

// The expert's car at time t of its path (interpolated between sub-steps).
void paint_ghost_car(Renderer2D& renderer, const ParkingPath& path, double t, float alpha = 0.5f);

}  // namespace sc
