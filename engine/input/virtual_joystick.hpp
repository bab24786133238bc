#pragma once
// The on-screen joystick of the paper's user study, dragged with the mouse. Pure logic in the caller's
// pixel coordinates (y down, e.g. SDL window coordinates): the renderer draws it from view(), the input
// code feeds it press/drag/release. Knob offset / radius is a point of the unit disc; x -> steering,
// up -> forward, through the disc->square map (stick_geometry.hpp) so the whole action square is reachable
// and any action (e.g. the expert's during a demo) can be shown exactly.
#include "engine/input/drive_action.hpp"
#include "engine/input/stick_geometry.hpp"

namespace sc::input {

// What the renderer needs to draw a stick: base circle and knob centre, in pixels.
struct JoystickView {
  Vec2 centre;
  double radius = 0.0;
  Vec2 knob;
};

// Where the knob sits for action u on a stick with the given base (inverse of the drag mapping).
// Used to show "the expert's stick" during demonstrations. u is sanitised first.
JoystickView joystick_view_for_action(const DriveAction& u, Vec2 centre, double radius);

// The action a knob at `knob` commands on a stick with the given base (knob clamped to the circle).
DriveAction action_for_knob(Vec2 knob, Vec2 centre, double radius);

class VirtualJoystick {
 public:
  // Throws InputError unless radius is finite and > 0 and the centre is finite.
  VirtualJoystick(Vec2 centre, double radius);

  // Moves/resizes the base (window resized); a held knob keeps its action.
  void set_base(Vec2 centre, double radius);

  // A press inside the base circle grabs the knob, which jumps under the pointer; a press outside is
  // ignored (returns false) so clicks elsewhere in the window never steer the car.
  bool press(Vec2 pointer);
  // While grabbed the knob follows the pointer, clamped to the base circle along the pointer's direction.
  void drag(Vec2 pointer);
  // The knob springs back to the centre (neutral action), like a real spring-loaded stick.
  void release();

  bool grabbed() const { return grabbed_; }
  JoystickView view() const;
  DriveAction action() const;

 private:
  Vec2 centre_;
  double radius_;
  Vec2 offset_;  // knob - centre as a point of the unit disc (y down)
  bool grabbed_ = false;
};

}  // namespace sc::input
