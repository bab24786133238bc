#include "app/gui/screen_host.hpp"

namespace sc {

ScreenHost::ScreenHost(GlContext& context, AppServices& services, const std::string& first_screen,
                       int max_steps_per_frame)
    : context_(context),
      services_(services),
      imgui_(context),
      renderer_(context),
      clock_(kSimulationStep, max_steps_per_frame),
      navigator_(services, first_screen) {}

void ScreenHost::frame(const FrameInput& input, double elapsed_seconds) {
  const ClockAdvance advance = clock_.advance(elapsed_seconds);
  for (int i = 0; i < advance.steps; ++i) {
    navigator_.current().update(i == 0 ? input : input.without_edges(), clock_.step_seconds());
    screen_time_ += clock_.step_seconds();
  }
  imgui_.begin_frame(elapsed_seconds);
  renderer_.begin_frame(navigator_.current().background());
  UiContext ui{renderer_,
               imgui_.fonts(),
               imgui_.scale(),
               context_.width(),
               context_.height(),
               advance.alpha,
               screen_time_ + advance.alpha * clock_.step_seconds(),
               input,
               navigator_,
               services_};
  navigator_.current().draw(ui);
  renderer_.end_frame();
  imgui_.end_frame();
  if (navigator_.apply_pending()) {
    clock_.reset();
    screen_time_ = 0;
  }
}

}  // namespace sc
