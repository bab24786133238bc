#include "engine/render/imgui_layer.hpp"

#include <SDL_scancode.h>
#include <backends/imgui_impl_opengl3.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "engine/core/asset_paths.hpp"
#include "engine/core/error.hpp"
#include "engine/render/imgui_fan_balance.hpp"

namespace sc {
namespace {

// ImGui 1.86 reads keys through io.KeyMap -> io.KeysDown[] and asserts that keyboard navigation keys are mapped.
// We use SDL scancodes (as its SDL backend does, which re-sets the same map in the window), so headless runs
// and scripted tests can press keys the same way.
void map_keys_to_sdl_scancodes(ImGuiIO& io) {
  io.KeyMap[ImGuiKey_Tab] = SDL_SCANCODE_TAB;
  io.KeyMap[ImGuiKey_LeftArrow] = SDL_SCANCODE_LEFT;
  io.KeyMap[ImGuiKey_RightArrow] = SDL_SCANCODE_RIGHT;
  io.KeyMap[ImGuiKey_UpArrow] = SDL_SCANCODE_UP;
  io.KeyMap[ImGuiKey_DownArrow] = SDL_SCANCODE_DOWN;
  io.KeyMap[ImGuiKey_PageUp] = SDL_SCANCODE_PAGEUP;
  io.KeyMap[ImGuiKey_PageDown] = SDL_SCANCODE_PAGEDOWN;
  io.KeyMap[ImGuiKey_Home] = SDL_SCANCODE_HOME;
  io.KeyMap[ImGuiKey_End] = SDL_SCANCODE_END;
  io.KeyMap[ImGuiKey_Insert] = SDL_SCANCODE_INSERT;
  io.KeyMap[ImGuiKey_Delete] = SDL_SCANCODE_DELETE;
  io.KeyMap[ImGuiKey_Backspace] = SDL_SCANCODE_BACKSPACE;
  io.KeyMap[ImGuiKey_Space] = SDL_SCANCODE_SPACE;
  io.KeyMap[ImGuiKey_Enter] = SDL_SCANCODE_RETURN;
  io.KeyMap[ImGuiKey_Escape] = SDL_SCANCODE_ESCAPE;
  io.KeyMap[ImGuiKey_KeyPadEnter] = SDL_SCANCODE_KP_ENTER;
  io.KeyMap[ImGuiKey_A] = SDL_SCANCODE_A;
  io.KeyMap[ImGuiKey_C] = SDL_SCANCODE_C;
  io.KeyMap[ImGuiKey_V] = SDL_SCANCODE_V;
  io.KeyMap[ImGuiKey_X] = SDL_SCANCODE_X;
  io.KeyMap[ImGuiKey_Y] = SDL_SCANCODE_Y;
  io.KeyMap[ImGuiKey_Z] = SDL_SCANCODE_Z;
}

}  // namespace

ImGuiLayer::ImGuiLayer(GlContext& context) : context_(context) {
  // Resolve the fonts before touching ImGui: a missing asset must be a clean error, not an ImGui assert.
  (void)asset_path("fonts/DejaVuSans.ttf");
  (void)asset_path("fonts/DejaVuSans-Bold.ttf");
  IMGUI_CHECKVERSION();
  imgui_ = ImGui::CreateContext();
  ImGui::SetCurrentContext(imgui_);
  ImGuiIO& io = ImGui::GetIO();
  io.IniFilename = nullptr;  // no imgui.ini in the working directory; layouts are code, screenshots reproducible
  io.LogFilename = nullptr;
  io.ConfigFlags |= ImGuiConfigFlags_NavEnableKeyboard | ImGuiConfigFlags_NavEnableGamepad;
  map_keys_to_sdl_scancodes(io);
  context_.make_current();
  if (!ImGui_ImplOpenGL3_Init("#version 330 core")) {
    ImGui::DestroyContext(imgui_);
    throw InputError(std::string(context.backend_name()) + " OpenGL context", "ImGui OpenGL3 backend failed to start");
  }
  try {
    solid_fills_ = std::make_unique<ImGuiSolidFills>(context_.gl());
  } catch (...) {  // a missing shader file: leave no half-started backend behind
    ImGui_ImplOpenGL3_Shutdown();
    ImGui::DestroyContext(imgui_);
    throw;
  }
  rebuild_fonts_and_style(scale_for_height(context_.height()));
}

ImGuiLayer::~ImGuiLayer() {
  make_current();
  context_.make_current();
  solid_fills_.reset();
  ImGui_ImplOpenGL3_Shutdown();
  ImGui::DestroyContext(imgui_);
}

void ImGuiLayer::make_current() const { ImGui::SetCurrentContext(imgui_); }

float ImGuiLayer::scale_for_height(int framebuffer_height) {
  const float raw = static_cast<float>(framebuffer_height) / 720.0f;
  return std::clamp(std::round(raw * 8.0f) / 8.0f, 0.75f, 4.0f);
}

void ImGuiLayer::rebuild_fonts_and_style(float scale) {
  scale_ = scale;
  ImGuiIO& io = ImGui::GetIO();
  io.Fonts->Clear();
  ImFontConfig config;
  config.OversampleH = 2;
  config.OversampleV = 1;
  const std::string regular = asset_path("fonts/DejaVuSans.ttf").string();
  const std::string bold = asset_path("fonts/DejaVuSans-Bold.ttf").string();
  fonts_.body = io.Fonts->AddFontFromFileTTF(regular.c_str(), std::round(18.0f * scale), &config);
  fonts_.bold = io.Fonts->AddFontFromFileTTF(bold.c_str(), std::round(18.0f * scale), &config);
  fonts_.heading = io.Fonts->AddFontFromFileTTF(bold.c_str(), std::round(30.0f * scale), &config);
  fonts_.title = io.Fonts->AddFontFromFileTTF(bold.c_str(), std::round(48.0f * scale), &config);
  if (fonts_.body == nullptr || fonts_.bold == nullptr || fonts_.heading == nullptr || fonts_.title == nullptr)
    throw InputError(regular, "font could not be loaded");
  io.FontDefault = fonts_.body;
  ImGui_ImplOpenGL3_DestroyFontsTexture();
  if (!ImGui_ImplOpenGL3_CreateFontsTexture()) throw InputError("ImGui", "font texture upload failed");
  ImGui::GetStyle() = ImGuiStyle();
  apply_skillcoach_style(ImGui::GetStyle(), scale);
}

void ImGuiLayer::hold_scale(float scale) {
  held_scale_ = std::clamp(scale, 0.75f, 4.0f);
  make_current();
  if (*held_scale_ != scale_) rebuild_fonts_and_style(*held_scale_);
}

void ImGuiLayer::begin_frame(double dt_seconds) {
  make_current();
  context_.make_current();
  const int w = context_.width(), h = context_.height();
  if (const float wanted = held_scale_.value_or(scale_for_height(h)); wanted != scale_) rebuild_fonts_and_style(wanted);
  ImGuiIO& io = ImGui::GetIO();
  io.DisplaySize = ImVec2(static_cast<float>(w), static_cast<float>(h));
  io.DisplayFramebufferScale = ImVec2(1, 1);
  io.DeltaTime = static_cast<float>(std::clamp(dt_seconds, 1e-4, 0.25));
  ImGui_ImplOpenGL3_NewFrame();
  ImGui::NewFrame();
}

void ImGuiLayer::end_frame() {
  make_current();
  ImGui::Render();
  // Cheaper triangles for a software rasteriser, same pixels (the two headers say why).
  balance_convex_fans(*ImGui::GetDrawData());
  solid_fills_->split(*ImGui::GetDrawData());
  context_.gl().BindFramebuffer(GL_FRAMEBUFFER, context_.target_framebuffer());
  ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
}

void apply_skillcoach_style(ImGuiStyle& style, float scale) {
  style.WindowPadding = ImVec2(20, 18);
  style.FramePadding = ImVec2(14, 8);
  style.ItemSpacing = ImVec2(12, 10);
  style.ItemInnerSpacing = ImVec2(8, 6);
  style.WindowRounding = 10;
  style.ChildRounding = 8;
  style.FrameRounding = 6;
  style.PopupRounding = 6;
  style.GrabRounding = 6;
  style.TabRounding = 6;
  style.ScrollbarRounding = 8;
  style.WindowBorderSize = 0;
  style.FrameBorderSize = 0;
  style.ScrollbarSize = 14;
  style.WindowTitleAlign = ImVec2(0.5f, 0.5f);
  style.ScaleAllSizes(scale);

  auto rgb = [](unsigned hex, float a = 1.0f) {
    return ImVec4(static_cast<float>((hex >> 16) & 0xff) / 255.0f, static_cast<float>((hex >> 8) & 0xff) / 255.0f,
                  static_cast<float>(hex & 0xff) / 255.0f, a);
  };
  ImVec4* c = style.Colors;
  c[ImGuiCol_Text] = rgb(0xe8ecf2);
  c[ImGuiCol_TextDisabled] = rgb(0x8a93a3);
  c[ImGuiCol_WindowBg] = rgb(0x1b2029);
  c[ImGuiCol_ChildBg] = rgb(0x222835);
  c[ImGuiCol_PopupBg] = rgb(0x222835);
  c[ImGuiCol_Border] = rgb(0x39414f);
  c[ImGuiCol_FrameBg] = rgb(0x2a3140);
  c[ImGuiCol_FrameBgHovered] = rgb(0x343d4f);
  c[ImGuiCol_FrameBgActive] = rgb(0x3d4860);
  c[ImGuiCol_TitleBg] = rgb(0x1b2029);
  c[ImGuiCol_TitleBgActive] = rgb(0x222835);
  c[ImGuiCol_Button] = rgb(0x2f3849);
  c[ImGuiCol_ButtonHovered] = rgb(0x3b4760);
  c[ImGuiCol_ButtonActive] = rgb(0x2f6fd8);
  c[ImGuiCol_Header] = rgb(0x2f6fd8, 0.55f);
  c[ImGuiCol_HeaderHovered] = rgb(0x2f6fd8, 0.75f);
  c[ImGuiCol_HeaderActive] = rgb(0x2f6fd8);
  c[ImGuiCol_CheckMark] = rgb(0x5b9bff);
  c[ImGuiCol_SliderGrab] = rgb(0x5b9bff);
  c[ImGuiCol_SliderGrabActive] = rgb(0x8ab8ff);
  c[ImGuiCol_Separator] = rgb(0x39414f);
  c[ImGuiCol_NavHighlight] = rgb(0x8ab8ff);
  c[ImGuiCol_PlotHistogram] = rgb(0x5b9bff);
}

}  // namespace sc
