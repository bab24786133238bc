#pragma once
// ImGui draws everything with one shader that multiplies the vertex colour by a font-atlas texel; its panels,
// child windows and frames use the atlas's white texel. On a software rasteriser (llvmpipe) that texture
// fetch is most of a pixel's cost, and the panels cover most of a screen: on the review screen the panel
// backgrounds cost more than the whole lot (docs/rendering.md). This moves every large run of such solid
// triangles into a draw with a shader that outputs the vertex colour alone (shaders/imgui_solid.*), in
// the same order, so the pixels stay the same (the white texel is exactly 1). Small runs (a checkbox, a
// separator) stay in ImGui's draw: a shader switch costs more than it saves on a few pixels.
//
//   ImGui::Render();
//   solid_fills.split(*ImGui::GetDrawData());   // inserts callbacks that switch programs
//   ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
#include <imgui.h>

#include <span>
#include <vector>

#include "engine/render/gl_functions.hpp"
#include "engine/render/shader_program.hpp"

namespace sc {

// A run of consecutive solid triangles below this many pixels is left in ImGui's textured draw.
inline constexpr float kMinSolidRunPixels = 4096.0f;

// A solid triangle: all three vertices on `white_uv`. Index ranges [first, first + count) of triangles (in
// index units, multiples of 3) that are runs of solid triangles covering at least `min_pixels` together.
struct IndexRange {
  unsigned first = 0;
  unsigned count = 0;
};
std::vector<IndexRange> solid_runs(std::span<const ImDrawIdx> indices, std::span<const ImDrawVert> vertices,
                                   ImVec2 white_uv, float min_pixels = kMinSolidRunPixels);

class ImGuiSolidFills {
 public:
  explicit ImGuiSolidFills(const GlFunctions& gl);
  ImGuiSolidFills(const ImGuiSolidFills&) = delete;
  ImGuiSolidFills& operator=(const ImGuiSolidFills&) = delete;

  // Splits the frame's draw commands around solid runs; the stock backend then draws them in order, calling
  // back into this object to switch to the solid program and back. Keep this object alive until drawn.
  void split(ImDrawData& draw_data);

 private:
  static void use_solid_program(const ImDrawList* list, const ImDrawCmd* cmd);

  const GlFunctions& gl_;
  ShaderProgram program_;
  GLint projection_uniform_ = -1;
  float projection_[16] = {};
  std::vector<ImDrawCmd> commands_;
};

}  // namespace sc
