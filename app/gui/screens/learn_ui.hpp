#pragma once
// Small shared pieces of the trainer's screens: the centred card every page uses, the primary button and
// the keyboard/gamepad "confirm" edge (Enter, Space or the gamepad's A), so menus work without a mouse.
#include <imgui.h>

#include <string>

#include "app/gui/screen.hpp"

namespace sc::learn_ui {

// A centred, undecorated window `width` (at UI scale 1) wide; returns after ImGui::Begin.
void begin_card(UiContext& ui, const char* id, float width, float y_anchor = 0.5f);
void end_card();
void title(UiContext& ui, const char* text);
void heading(UiContext& ui, const char* text);
void muted_wrapped(const char* text);
// A full-width (or `width` px at scale 1) blue button; true when clicked.
bool primary_button(UiContext& ui, const char* label, float width = 0.0f);
// Enter, keypad Enter, Space or gamepad A pressed this frame (and no text field has the keyboard).
bool confirm_pressed(const FrameInput& input);
// Esc or gamepad Start pressed this frame.
bool pause_pressed(const FrameInput& input);
// The trial screens' top bar (full width, 56 px at scale 1) with `title` in bold; returns after the title,
// on the same line, for the screen's own hints. Close with end_header_bar().
void begin_header_bar(UiContext& ui, const char* id, const std::string& title);
void end_header_bar();
// "-0.123 (0 is the expert's result)".
std::string reward_text(double reward);

}  // namespace sc::learn_ui
