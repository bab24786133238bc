#include "engine/render/imgui_solid_fills.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <iterator>

namespace sc {
namespace {

constexpr GLuint kPositionLocation = 0;  // as in shaders/imgui_solid.vert
constexpr GLuint kColorLocation = 2;

bool on_white(const ImDrawVert& v, ImVec2 white_uv) { return v.uv.x == white_uv.x && v.uv.y == white_uv.y; }

float triangle_pixels(const ImDrawVert& a, const ImDrawVert& b, const ImDrawVert& c) {
  return 0.5f * std::abs((b.pos.x - a.pos.x) * (c.pos.y - a.pos.y) - (b.pos.y - a.pos.y) * (c.pos.x - a.pos.x));
}

}  // namespace

std::vector<IndexRange> solid_runs(std::span<const ImDrawIdx> indices, std::span<const ImDrawVert> vertices,
                                   ImVec2 white_uv, float min_pixels) {
  std::vector<IndexRange> runs;
  IndexRange run;
  float run_pixels = 0;
  auto close_run = [&](unsigned end) {
    if (end > run.first && run_pixels >= min_pixels) runs.push_back({run.first, end - run.first});
    run = {end + 3, 0};
    run_pixels = 0;
  };
  const unsigned count = static_cast<unsigned>(indices.size() / 3 * 3);
  for (unsigned i = 0; i < count; i += 3) {
    const ImDrawIdx a = indices[i], b = indices[i + 1], c = indices[i + 2];
    const bool solid = a < vertices.size() && b < vertices.size() && c < vertices.size() &&
                       on_white(vertices[a], white_uv) && on_white(vertices[b], white_uv) &&
                       on_white(vertices[c], white_uv);
    if (solid)
      run_pixels += triangle_pixels(vertices[a], vertices[b], vertices[c]);
    else
      close_run(i);
  }
  close_run(count);
  return runs;
}

ImGuiSolidFills::ImGuiSolidFills(const GlFunctions& gl)
    : gl_(gl), program_(gl, "imgui_solid.vert", "imgui_solid.frag") {
  projection_uniform_ = program_.uniform("ProjMtx");
}

void ImGuiSolidFills::use_solid_program(const ImDrawList*, const ImDrawCmd* cmd) {
  const auto& self = *static_cast<const ImGuiSolidFills*>(cmd->UserCallbackData);
  const GlFunctions& gl = self.gl_;
  gl.UseProgram(self.program_.id());
  gl.UniformMatrix4fv(self.projection_uniform_, 1, GL_FALSE, self.projection_);
  // The backend's vertex array and buffer stay bound; point our attributes at its ImDrawVert layout (the
  // backend's own state comes back with ImDrawCallback_ResetRenderState after the run).
  gl.EnableVertexAttribArray(kPositionLocation);
  gl.VertexAttribPointer(kPositionLocation, 2, GL_FLOAT, GL_FALSE, sizeof(ImDrawVert),
                         reinterpret_cast<void*>(offsetof(ImDrawVert, pos)));
  gl.EnableVertexAttribArray(kColorLocation);
  gl.VertexAttribPointer(kColorLocation, 4, GL_UNSIGNED_BYTE, GL_TRUE, sizeof(ImDrawVert),
                         reinterpret_cast<void*>(offsetof(ImDrawVert, col)));
}

void ImGuiSolidFills::split(ImDrawData& draw_data) {
  // The backend's orthographic projection (top-left origin).
  const float l = draw_data.DisplayPos.x, r = l + draw_data.DisplaySize.x;
  const float t = draw_data.DisplayPos.y, b = t + draw_data.DisplaySize.y;
  const float projection[16] = {2.0f / (r - l), 0, 0, 0, 0, 2.0f / (t - b), 0, 0, 0, 0, -1.0f, 0,
                                (r + l) / (l - r), (t + b) / (b - t), 0, 1};
  std::copy(std::begin(projection), std::end(projection), projection_);
  const ImVec2 white_uv = ImGui::GetFontTexUvWhitePixel();
  for (int n = 0; n < draw_data.CmdListsCount; ++n) {
    ImDrawList& list = *draw_data.CmdLists[n];
    const std::span<const ImDrawIdx> indices(list.IdxBuffer.Data, static_cast<std::size_t>(list.IdxBuffer.Size));
    const std::span<const ImDrawVert> vertices(list.VtxBuffer.Data, static_cast<std::size_t>(list.VtxBuffer.Size));
    commands_.clear();
    for (const ImDrawCmd& cmd : list.CmdBuffer) {
      const bool drawable = cmd.UserCallback == nullptr && cmd.VtxOffset <= vertices.size() &&
                            cmd.IdxOffset + cmd.ElemCount <= indices.size();
      const auto runs = drawable ? solid_runs(indices.subspan(cmd.IdxOffset, cmd.ElemCount),
                                              vertices.subspan(cmd.VtxOffset), white_uv)
                                 : std::vector<IndexRange>{};
      if (runs.empty()) {
        commands_.push_back(cmd);
        continue;
      }
      auto part = [&](unsigned first, unsigned count) {
        if (count == 0) return;
        ImDrawCmd piece = cmd;
        piece.IdxOffset = cmd.IdxOffset + first;
        piece.ElemCount = count;
        commands_.push_back(piece);
      };
      auto callback = [&](ImDrawCallback function) {
        ImDrawCmd call = cmd;
        call.ElemCount = 0;
        call.UserCallback = function;
        call.UserCallbackData = this;
        commands_.push_back(call);
      };
      unsigned done = 0;
      for (const IndexRange& run : runs) {
        part(done, run.first - done);
        callback(&ImGuiSolidFills::use_solid_program);
        part(run.first, run.count);
        callback(ImDrawCallback_ResetRenderState);
        done = run.first + run.count;
      }
      part(done, cmd.ElemCount - done);
    }
    list.CmdBuffer.resize(static_cast<int>(commands_.size()));
    std::copy(commands_.begin(), commands_.end(), list.CmdBuffer.Data);
  }
}

}  // namespace sc
