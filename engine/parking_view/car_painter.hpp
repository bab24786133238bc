#pragma once
// The parking car in the reference look (reference-facts §1.9), drawn in world metres so it is exact at any
// zoom: 5x2 m body, two headlights at the front, a roof, the dark ring marking the front ("the black circle"
// of the paper) and four tyres on the body corners, the front pair turned by the steering angle.
// The same painter draws the learner's car, parked cars (another body colour) and ghost cars (translucent).
#include "engine/render/draw_types.hpp"
#include "engine/render/renderer2d.hpp"

namespace sc {

// Where a car is and how its front wheels are turned (world metres and radians; heading turns +x toward
// +y, i.e. clockwise on the y-down lot; steering > 0 turns the front wheels the same way).
struct CarPose {
  Vec2f center;
  float heading = 0;
  float steering = 0;
};

struct CarLook {
  Color body;
  Color headlight;
  Color roof;
  Color outline;
  Color ring;
  Color tyre;
};

// The reference derives headlights (body / 0.68, capped) and roof (body * 0.83) from the body colour;
// `alpha` applies to every part (ghost cars).
CarLook car_look_from_body(Color body, float alpha = 1.0f);
// The learner's car: yellow-orange (235,189,52) with the reference's outline, ring and tyres.
CarLook reference_car_look();
// Parked cars: the same shapes in steel blue, so they read as "other cars", never as the learner's.
CarLook parked_car_look();
// The expert's ghost car: pale cyan, translucent.
CarLook ghost_car_look(float alpha = 0.5f);

// Draws the car (body, headlights, roof, outline, ring, tyres: the reference's order).
void paint_car(Renderer2D& renderer, const CarPose& pose, const CarLook& look);

}  // namespace sc
