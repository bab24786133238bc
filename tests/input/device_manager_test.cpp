// DeviceManager against real SDL event traffic, with SDL's virtual gamepads (SDL >= 2.24) standing in for
// USB devices: attaching/detaching one produces the same CONTROLLERDEVICEADDED/REMOVED events as plugging
// and unplugging. Only the joystick/controller subsystems are initialised, so no display is needed.
#include "engine/input/device_manager.hpp"

#include <memory>
#include <stdexcept>

#include <gtest/gtest.h>

#include "engine/input/action_latch.hpp"

namespace sc::input {
namespace {

class DeviceManagerTest : public testing::Test {
 protected:
  void SetUp() override { ASSERT_EQ(SDL_Init(SDL_INIT_GAMECONTROLLER), 0) << SDL_GetError(); }
  void TearDown() override {
    devices_.reset();  // closes controllers before SDL goes away
    SDL_Quit();
  }

  DeviceManager& make_devices(InputSource source = InputSource::Gamepad, GamepadConfig config = {}) {
    devices_ = std::make_unique<DeviceManager>(source, config);
    return *devices_;
  }

  static SDL_JoystickID attach(const char* name) {
    SDL_VirtualJoystickDesc desc{};
    desc.version = SDL_VIRTUAL_JOYSTICK_DESC_VERSION;
    desc.type = SDL_JOYSTICK_TYPE_GAMECONTROLLER;
    desc.naxes = SDL_CONTROLLER_AXIS_MAX;
    desc.nbuttons = SDL_CONTROLLER_BUTTON_MAX;
    desc.name = name;
    const int index = SDL_JoystickAttachVirtualEx(&desc);
    if (index < 0) throw std::runtime_error(SDL_GetError());
    return SDL_JoystickGetDeviceInstanceID(index);
  }

  // Device indices shift when devices go away, so look the index up from the stable instance id.
  static void detach(SDL_JoystickID id) {
    for (int i = 0; i < SDL_NumJoysticks(); ++i)
      if (SDL_JoystickGetDeviceInstanceID(i) == id) {
        ASSERT_EQ(SDL_JoystickDetachVirtual(i), 0) << SDL_GetError();
        return;
      }
    FAIL() << "no joystick with instance id " << id;
  }

  // Needs the device opened (by the DeviceManager) first.
  static void set_axis(SDL_JoystickID id, SDL_GameControllerAxis axis, Sint16 value) {
    ASSERT_EQ(SDL_JoystickSetVirtualAxis(SDL_JoystickFromInstanceID(id), axis, value), 0) << SDL_GetError();
  }
  static void set_button(SDL_JoystickID id, SDL_GameControllerButton button, bool down) {
    ASSERT_EQ(SDL_JoystickSetVirtualButton(SDL_JoystickFromInstanceID(id), button, down ? 1 : 0), 0);
  }

  // What the app's frame loop does with the event queue.
  void pump() {
    for (SDL_Event e; SDL_PollEvent(&e);) devices_->handle_event(e);
  }

  std::unique_ptr<DeviceManager> devices_;
};

TEST_F(DeviceManagerTest, GamepadConnectedMidSessionAppearsInTheList) {
  DeviceManager& devices = make_devices();
  pump();
  EXPECT_TRUE(devices.gamepads().empty());
  EXPECT_EQ(devices.state(), InputState::WaitingForGamepad);
  EXPECT_EQ(devices.action(), DriveAction{});

  const SDL_JoystickID a = attach("Pad A");
  pump();
  ASSERT_EQ(devices.gamepads().size(), 1u);
  EXPECT_EQ(devices.gamepads()[0].name, "Pad A");
  EXPECT_EQ(devices.gamepads()[0].instance_id, a);
  EXPECT_EQ(devices.state(), InputState::Ready);
  EXPECT_EQ(devices.status_message(), "Gamepad: Pad A");

  const SDL_JoystickID b = attach("Pad B");
  pump();
  ASSERT_EQ(devices.gamepads().size(), 2u);
  EXPECT_EQ(devices.gamepads()[1].instance_id, b);
  EXPECT_EQ(devices.active_gamepad()->instance_id, a);  // the one in use stays in use
}

TEST_F(DeviceManagerTest, GamepadPresentAtStartIsListedOnce) {
  attach("Early Pad");
  DeviceManager& devices = make_devices();
  ASSERT_EQ(devices.gamepads().size(), 1u);
  pump();  // SDL's own ADDED event for it must not open it a second time
  EXPECT_EQ(devices.gamepads().size(), 1u);
}

TEST_F(DeviceManagerTest, StickAndTriggersDriveTheAction) {
  DeviceManager& devices = make_devices();
  const SDL_JoystickID pad = attach("Pad");
  pump();
  set_axis(pad, SDL_CONTROLLER_AXIS_LEFTY, -32768);  // full up
  pump();
  EXPECT_EQ(devices.action(), (DriveAction{1.0, 0.0}));
  set_axis(pad, SDL_CONTROLLER_AXIS_LEFTY, 0);
  set_axis(pad, SDL_CONTROLLER_AXIS_LEFTX, 1000);  // inside the dead zone
  pump();
  EXPECT_EQ(devices.action(), DriveAction{});
  EXPECT_FALSE(devices.read().faulty);

  GamepadConfig triggers;
  triggers.throttle = ThrottleControl::Triggers;
  devices.set_gamepad_config(triggers);
  set_axis(pad, SDL_CONTROLLER_AXIS_TRIGGERLEFT, 32767);
  set_axis(pad, SDL_CONTROLLER_AXIS_LEFTX, -32768);
  pump();
  EXPECT_EQ(devices.action(), (DriveAction{-1.0, -1.0}));
}

TEST_F(DeviceManagerTest, UnplugMidTrialPausesKeepsTheRecordingAndResumesOnAnotherPad) {
  DeviceManager& devices = make_devices();
  const SDL_JoystickID first = attach("First Pad");
  pump();
  ActionLatch latch;
  // The app's loop: one sub-step per iteration while input is ready, none while paused.
  auto drive_substeps = [&](int n) {
    for (int i = 0; i < n; ++i) {
      pump();
      if (devices.state() == InputState::Ready) latch.next_substep(devices.action());
    }
  };
  set_axis(first, SDL_CONTROLLER_AXIS_LEFTY, -20000);
  drive_substeps(7);
  const RecordedActions before_unplug = latch.recorded();
  ASSERT_EQ(before_unplug.actions.size(), 3u);
  EXPECT_GT(before_unplug.actions[0].accel, 0.4);

  detach(first);
  pump();
  EXPECT_EQ(devices.state(), InputState::DeviceLost);
  EXPECT_NE(devices.status_message().find("'First Pad' was disconnected"), std::string::npos);
  EXPECT_NE(devices.status_message().find("paused"), std::string::npos);
  EXPECT_EQ(devices.action(), DriveAction{});
  EXPECT_TRUE(devices.gamepads().empty());
  drive_substeps(20);  // frames pass while paused: nothing is stepped or recorded, nothing is lost
  EXPECT_EQ(latch.substeps_done(), 7);
  EXPECT_EQ(latch.recorded().actions, before_unplug.actions);

  const SDL_JoystickID second = attach("Second Pad");
  pump();
  EXPECT_EQ(devices.state(), InputState::Ready);
  EXPECT_EQ(devices.active_gamepad()->instance_id, second);
  set_axis(second, SDL_CONTROLLER_AXIS_LEFTY, 32767);  // now reversing
  drive_substeps(5);
  ASSERT_EQ(latch.recorded().actions.size(), 4u);  // sub-steps 0, 3, 6, 9
  EXPECT_EQ(latch.recorded().actions[2], before_unplug.actions[2]);
  EXPECT_EQ(latch.recorded().actions[3].accel, -1.0);
}

TEST_F(DeviceManagerTest, LosingThePadInUsePausesEvenIfAnotherIsConnectedUntilItIsPickedUp) {
  DeviceManager& devices = make_devices();
  const SDL_JoystickID first = attach("First Pad");
  const SDL_JoystickID spare = attach("Spare Pad");
  pump();
  ASSERT_EQ(devices.active_gamepad()->instance_id, first);
  detach(first);
  pump();
  EXPECT_EQ(devices.state(), InputState::DeviceLost);
  set_button(spare, SDL_CONTROLLER_BUTTON_A, true);
  pump();
  EXPECT_EQ(devices.state(), InputState::Ready);
  EXPECT_EQ(devices.active_gamepad()->instance_id, spare);
}

TEST_F(DeviceManagerTest, SameDeviceReconnectedResumes) {
  DeviceManager& devices = make_devices();
  detach(attach("Flaky Pad"));
  pump();
  const SDL_JoystickID pad = attach("Flaky Pad");
  pump();
  // It was never in use in a lost state here: plug, unplug before use, plug again.
  EXPECT_EQ(devices.state(), InputState::Ready);
  detach(pad);
  pump();
  EXPECT_EQ(devices.state(), InputState::DeviceLost);
  attach("Flaky Pad");
  pump();
  EXPECT_EQ(devices.state(), InputState::Ready);
  EXPECT_EQ(devices.gamepads().size(), 1u);
}

TEST_F(DeviceManagerTest, UnplugDoesNotPauseWhenAnotherSourceIsInUse) {
  DeviceManager& devices = make_devices(InputSource::Keyboard);
  const SDL_JoystickID pad = attach("Idle Pad");
  pump();
  detach(pad);
  pump();
  EXPECT_EQ(devices.state(), InputState::Ready);
}

TEST_F(DeviceManagerTest, SwitchingSourceWhileLostContinuesTheTrial) {
  DeviceManager& devices = make_devices();
  const SDL_JoystickID pad = attach("Pad");
  pump();
  detach(pad);
  pump();
  ASSERT_EQ(devices.state(), InputState::DeviceLost);
  devices.set_source(InputSource::Keyboard);
  EXPECT_EQ(devices.state(), InputState::Ready);
  EXPECT_EQ(devices.status_message(), "Keyboard: arrows or WASD");
}

SDL_Event key_event(Uint32 type, SDL_Scancode scancode, Uint8 repeat = 0) {
  SDL_Event e{};
  e.type = type;
  e.key.type = type;
  e.key.state = type == SDL_KEYDOWN ? SDL_PRESSED : SDL_RELEASED;
  e.key.repeat = repeat;
  e.key.keysym.scancode = scancode;
  return e;
}

SDL_Event mouse_button(Uint32 type, int x, int y) {
  SDL_Event e{};
  e.type = type;
  e.button.type = type;
  e.button.button = SDL_BUTTON_LEFT;
  e.button.x = x;
  e.button.y = y;
  return e;
}

SDL_Event mouse_motion(int x, int y) {
  SDL_Event e{};
  e.type = SDL_MOUSEMOTION;
  e.motion.x = x;
  e.motion.y = y;
  return e;
}

TEST_F(DeviceManagerTest, KeyboardEventsDriveAndFocusLossReleasesKeys) {
  DeviceManager& devices = make_devices(InputSource::Keyboard);
  EXPECT_TRUE(devices.handle_event(key_event(SDL_KEYDOWN, SDL_SCANCODE_UP)));
  EXPECT_TRUE(devices.handle_event(key_event(SDL_KEYDOWN, SDL_SCANCODE_A)));
  EXPECT_FALSE(devices.handle_event(key_event(SDL_KEYDOWN, SDL_SCANCODE_SPACE)));
  EXPECT_EQ(devices.action(), (DriveAction{1.0, -1.0}));
  devices.handle_event(key_event(SDL_KEYUP, SDL_SCANCODE_A));
  EXPECT_EQ(devices.action(), (DriveAction{1.0, 0.0}));
  SDL_Event focus{};
  focus.type = SDL_WINDOWEVENT;
  focus.window.event = SDL_WINDOWEVENT_FOCUS_LOST;
  devices.handle_event(focus);
  EXPECT_EQ(devices.action(), DriveAction{});
}

TEST_F(DeviceManagerTest, MouseDragsTheVirtualJoystick) {
  DeviceManager& devices = make_devices(InputSource::VirtualJoystick);
  devices.virtual_joystick().set_base({300.0, 200.0}, 80.0);
  EXPECT_FALSE(devices.handle_event(mouse_button(SDL_MOUSEBUTTONDOWN, 10, 10)));  // a click elsewhere
  EXPECT_FALSE(devices.handle_event(mouse_button(SDL_MOUSEBUTTONUP, 10, 10)));
  EXPECT_TRUE(devices.handle_event(mouse_button(SDL_MOUSEBUTTONDOWN, 300, 160)));
  EXPECT_EQ(devices.action(), (DriveAction{0.5, 0.0}));
  EXPECT_TRUE(devices.handle_event(mouse_motion(380, 200)));
  EXPECT_EQ(devices.action(), (DriveAction{0.0, 1.0}));
  EXPECT_TRUE(devices.handle_event(mouse_button(SDL_MOUSEBUTTONUP, 380, 200)));
  EXPECT_EQ(devices.action(), DriveAction{});
  EXPECT_FALSE(devices.handle_event(mouse_motion(300, 120)));
}

}  // namespace
}  // namespace sc::input
