#include "app/gui/screens/learn_ui.hpp"

#include <cstdio>

namespace sc::learn_ui {

void begin_card(UiContext& ui, const char* id, float width, float y_anchor) {
  const float s = ui.ui_scale;
  ImGui::SetNextWindowPos(ImVec2(static_cast<float>(ui.width) * 0.5f, static_cast<float>(ui.height) * y_anchor),
                          ImGuiCond_Always, ImVec2(0.5f, y_anchor));
  ImGui::SetNextWindowSize(ImVec2(width * s, 0.0f), ImGuiCond_Always);
  ImGui::SetNextWindowBgAlpha(0.96f);
  ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(32.0f * s, 26.0f * s));
  ImGui::Begin(id, nullptr,
               ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoSavedSettings |
                   ImGuiWindowFlags_AlwaysAutoResize);
}

void begin_header_bar(UiContext& ui, const char* id, const std::string& title) {
  const float s = ui.ui_scale;
  ImGui::SetNextWindowPos(ImVec2(0, 0));
  ImGui::SetNextWindowSize(ImVec2(static_cast<float>(ui.width), 56 * s));
  ImGui::Begin(id, nullptr, ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoSavedSettings);
  ImGui::PushFont(ui.fonts.bold);
  ImGui::TextUnformatted(title.c_str());
  ImGui::PopFont();
  ImGui::SameLine(0, 30 * s);
}

void end_header_bar() { ImGui::End(); }

void end_card() {
  ImGui::End();
  ImGui::PopStyleVar();
}

void title(UiContext& ui, const char* text) {
  ImGui::PushFont(ui.fonts.heading);
  ImGui::TextUnformatted(text);
  ImGui::PopFont();
}

void heading(UiContext& ui, const char* text) {
  ImGui::PushFont(ui.fonts.bold);
  ImGui::TextUnformatted(text);
  ImGui::PopFont();
}

void muted_wrapped(const char* text) {
  ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyle().Colors[ImGuiCol_TextDisabled]);
  ImGui::TextWrapped("%s", text);
  ImGui::PopStyleColor();
}

bool primary_button(UiContext& ui, const char* label, float width) {
  const float w = width > 0 ? width * ui.ui_scale : ImGui::GetContentRegionAvail().x;
  ImGui::PushFont(ui.fonts.bold);
  ImGui::PushStyleColor(ImGuiCol_Button, ImVec4(0.18f, 0.44f, 0.85f, 1.0f));
  ImGui::PushStyleColor(ImGuiCol_ButtonHovered, ImVec4(0.25f, 0.52f, 0.93f, 1.0f));
  const bool clicked = ImGui::Button(label, ImVec2(w, 44.0f * ui.ui_scale));
  ImGui::PopStyleColor(2);
  ImGui::PopFont();
  return clicked;
}

bool confirm_pressed(const FrameInput& input) {
  if (input.ui_wants_keyboard) return false;
  if (input.keys_pressed[SDL_SCANCODE_RETURN] || input.keys_pressed[SDL_SCANCODE_KP_ENTER] ||
      input.keys_pressed[SDL_SCANCODE_SPACE])
    return true;
  return false;
}

bool pause_pressed(const FrameInput& input) { return input.keys_pressed[SDL_SCANCODE_ESCAPE]; }

std::string reward_text(double reward) {
  char text[64];
  std::snprintf(text, sizeof text, "%.3f", reward);
  return text;
}

}  // namespace sc::learn_ui
