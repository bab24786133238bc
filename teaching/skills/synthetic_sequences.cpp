#include "teaching/skills/synthetic_sequences.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "engine/core/rng.hpp"

namespace sc {

namespace {

void push_step(PlantedSequence& p, const std::vector<float>& state, float a0, float a1) {
  p.steps.states.insert(p.steps.states.end(), state.begin(), state.end());
  p.steps.actions.push_back(a0);
  p.steps.actions.push_back(a1);
}

}  // namespace

std::vector<PlantedSequence> constant_primitive_sequences(int count, int segments, int primitive_count, int min_length,
                                                          int max_length, int state_dim, std::uint64_t seed) {
  Rng rng(seed);
  // Distinct directions spread around the circle, magnitude 0.8 (inside the decoder's tanh range).
  std::vector<std::pair<float, float>> primitive;
  for (int i = 0; i < primitive_count; ++i) {
    const double angle = 2.0 * std::numbers::pi * i / primitive_count + 0.3;
    primitive.emplace_back(static_cast<float>(0.8 * std::cos(angle)), static_cast<float>(0.8 * std::sin(angle)));
  }
  std::vector<PlantedSequence> out;
  for (int n = 0; n < count; ++n) {
    PlantedSequence p;
    p.steps.action_dim = 2;
    p.steps.state_dim = state_dim;
    std::vector<float> state(static_cast<std::size_t>(state_dim), 0.0f);
    int previous = -1;
    for (int s = 0; s < segments; ++s) {
      int id;
      do id = static_cast<int>(rng.below(static_cast<std::uint64_t>(primitive_count)));
      while (id == previous);
      previous = id;
      const int len = min_length + static_cast<int>(rng.below(static_cast<std::uint64_t>(max_length - min_length + 1)));
      for (int t = 0; t < len; ++t) {
        push_step(p, state, primitive[static_cast<std::size_t>(id)].first,
                  primitive[static_cast<std::size_t>(id)].second);
        if (state_dim >= 2) {
          state[0] += 0.1f * primitive[static_cast<std::size_t>(id)].first;
          state[1] += 0.1f * primitive[static_cast<std::size_t>(id)].second;
        }
      }
      p.boundaries.push_back(p.steps.length());
      p.primitives.push_back(id);
    }
    out.push_back(std::move(p));
  }
  return out;
}

std::vector<PlantedSequence> repeated_symbol_sequences(int count, int segments, int symbol_count, int min_length,
                                                       int max_length, std::uint64_t symbol_seed, std::uint64_t seed) {
  // Steps are one of 16 directions; symbol i starts with direction i and ends with direction i + 8 (mod
  // 16, so symbol_count <= 8 keeps every first and every last step distinct: each edge is visible in one
  // step); the steps between are random.
  Rng symbol_rng(symbol_seed);
  auto step_of = [](std::uint64_t direction) {
    const double angle = 2.0 * std::numbers::pi * static_cast<double>(direction % 16) / 16.0;
    return std::pair<float, float>(static_cast<float>(0.8 * std::cos(angle)),
                                   static_cast<float>(0.8 * std::sin(angle)));
  };
  std::vector<std::vector<std::pair<float, float>>> symbols(static_cast<std::size_t>(symbol_count));
  for (std::size_t i = 0; i < symbols.size(); ++i) {
    const int len =
        min_length + static_cast<int>(symbol_rng.below(static_cast<std::uint64_t>(max_length - min_length + 1)));
    symbols[i].push_back(step_of(i));
    for (int t = 1; t + 1 < len; ++t) symbols[i].push_back(step_of(symbol_rng.below(16)));
    symbols[i].push_back(step_of(i + 8));
  }
  Rng rng(seed);
  std::vector<PlantedSequence> out;
  for (int n = 0; n < count; ++n) {
    PlantedSequence p;
    p.steps.action_dim = 2;
    int previous = -1;
    for (int s = 0; s < segments; ++s) {
      int id;
      do id = static_cast<int>(rng.below(static_cast<std::uint64_t>(symbol_count)));
      while (id == previous);
      previous = id;
      for (const auto& [a0, a1] : symbols[static_cast<std::size_t>(id)]) push_step(p, {}, a0, a1);
      p.boundaries.push_back(p.steps.length());
      p.primitives.push_back(id);
    }
    out.push_back(std::move(p));
  }
  return out;
}

std::vector<PlantedSequence> parking_like_sequences(int count, int min_length, int max_length, std::uint64_t seed) {
  Rng rng(seed);
  std::vector<PlantedSequence> out;
  for (int n = 0; n < count; ++n) {
    PlantedSequence p;
    p.steps.action_dim = 2;
    p.steps.state_dim = 12;
    const int len = min_length + static_cast<int>(rng.below(static_cast<std::uint64_t>(max_length - min_length + 1)));
    const int parts = 2 + static_cast<int>(rng.below(2));
    double x = 0, y = 0, heading = rng.uniform(0.0, 2.0 * std::numbers::pi), speed = 0;
    const double goal_x = 0.04 * static_cast<double>(rng.below(15)) - 0.30, goal_y = 0.14;
    int part = 0, part_end = len / parts;
    double accel = rng.uniform(-1, 1), steer = rng.uniform(-0.8, 0.8);
    for (int t = 0; t < len; ++t) {
      if (t == part_end && part + 1 < parts) {
        p.boundaries.push_back(t);
        p.primitives.push_back(accel < 0 ? 0 : (steer < 0 ? 1 : 2));
        ++part;
        part_end = part + 1 == parts ? len : t + len / parts;
        accel = rng.uniform(-1, 1);
        steer = rng.uniform(-0.8, 0.8);
      }
      const std::vector<float> state{static_cast<float>(x / 100),
                                     static_cast<float>(y / 100),
                                     static_cast<float>(speed * std::cos(heading) / 5),
                                     static_cast<float>(speed * std::sin(heading) / 5),
                                     static_cast<float>(std::cos(heading)),
                                     static_cast<float>(std::sin(heading)),
                                     static_cast<float>(goal_x),
                                     static_cast<float>(goal_y),
                                     0.0f,
                                     0.0f,
                                     0.0f,
                                     1.0f};
      const double a = std::clamp(accel + 0.1 * rng.normal(), -0.99, 0.99);
      const double st = std::clamp(steer + 0.1 * rng.normal(), -0.99, 0.99);
      push_step(p, state, static_cast<float>(a), static_cast<float>(st));
      for (int sub = 0; sub < 3; ++sub) {  // kinematic bicycle, 3 sub-steps of 1/15 s (reference §1.5)
        const double beta = std::atan(0.5 * std::tan(st * std::numbers::pi / 4));
        x += speed * std::cos(heading + beta) / 15;
        y += speed * std::sin(heading + beta) / 15;
        heading += speed * std::sin(beta) / 2.5 / 15;
        speed += 5 * a / 15;
      }
    }
    p.boundaries.push_back(len);
    p.primitives.push_back(accel < 0 ? 0 : (steer < 0 ? 1 : 2));
    out.push_back(std::move(p));
  }
  return out;
}

std::vector<PlantedSequence> writing_like_sequences(int count, int symbols, std::uint64_t seed) {
  Rng rng(seed);
  std::vector<PlantedSequence> out;
  const std::vector<float> no_state;
  for (int n = 0; n < count; ++n) {
    PlantedSequence p;
    p.steps.action_dim = 2;
    for (int s = 0; s < symbols; ++s) {
      const bool connector = rng.uniform() < 0.45;
      if (connector) {
        for (int t = 0; t < 20; ++t) push_step(p, no_state, 1.0f, 0.0f);
        p.primitives.push_back(0);
      } else {
        // A curved stroke: the heading turns at a rate that itself changes a few times.
        const int len = 180 + static_cast<int>(rng.below(241));
        double heading = rng.uniform(-std::numbers::pi, std::numbers::pi);
        double turn = rng.uniform(-0.03, 0.03);
        for (int t = 0; t < len; ++t) {
          if (t % 60 == 0) turn = rng.uniform(-0.04, 0.04);
          heading += turn;
          push_step(p, no_state, static_cast<float>(std::cos(heading)), static_cast<float>(std::sin(heading)));
        }
        p.primitives.push_back(1);
      }
      p.boundaries.push_back(p.steps.length());
    }
    out.push_back(std::move(p));
  }
  return out;
}

}  // namespace sc
