#pragma once
// The parking lot and its goal in world metres (reference-facts §1.9): grey ground (100,100,100), a white
// line along each long side of every spot, walls and parked cars of our "parked" variant, and the goal:
// the reference's light-blue 2x2 m square plus the outline of the target car pose in the spot, with its
// front marked, so a learner sees where and which way to park. Reverse-in goals are amber, not blue.
#include <imgui.h>

#include "engine/parking/parking_lot.hpp"
#include "engine/render/camera2d.hpp"
#include "engine/render/renderer2d.hpp"

namespace sc {

namespace parking_view {
inline constexpr Color kGround = Color::hex(0x646464);  // (100,100,100)
inline constexpr Color kLaneLine = Color::hex(0xffffff);
inline constexpr float kLaneLineWidth = 2.0f / 7.0f;  // int(0.3 * 7) = 2 px at 7 px/m
inline constexpr Color kWall = Color::hex(0x3a3a3e);
inline constexpr Color kWallEdge = Color::hex(0x8a8a90);
inline constexpr Color kGoalFill = Color::hex(0x64c8ff);     // (100,200,255)
inline constexpr Color kGoalOutline = Color::hex(0x3c3c3c);  // (60,60,60)
inline constexpr Color kReverseGoal = Color::hex(0xffae3c);  // reverse-in target: amber
}  // namespace parking_view

// Fills the camera's whole visible world with the ground colour, then the spot lines, the walls and the
// parked cars, as a static layer (Renderer2D::begin_static_layer). Call after Renderer2D::set_camera().
void paint_lot(Renderer2D& renderer, const ParkingLayout& layout);

// The goal landmark and the target pose of the car (`goal` as from goal_pose(scenario)).
void paint_goal(Renderer2D& renderer, const Pose& goal, bool reverse_in);

// Spot numbers (0..29, the scenario's goal_spot) at the aisle end of every spot, with ImGui into `draw_list`
// (default: the background draw list). Optional: for picking a goal spot.
void label_spots(const Camera2D& camera, ImDrawList* draw_list = nullptr);

}  // namespace sc
