#include "app/gui/app_services.hpp"

namespace sc {

std::string describe(const DeviceChoice& device) {
  switch (device.kind) {
    case DeviceKind::gamepad:
      return "Gamepad: " + device.gamepad_name;
    case DeviceKind::mouse_joystick:
      return "Mouse joystick";
    case DeviceKind::keyboard:
      return "Keyboard";
    case DeviceKind::mouse_pen:
      return "Mouse or trackpad";
  }
  return "unknown device";
}

}  // namespace sc
