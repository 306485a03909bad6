// Interactive quality's frame budget: while the scene moves, the window draws the share of the
// strands drawn beyond the simulated ones (children; followers, for which the simulated guides
// stand in) that the budget allows, measured from the last frames' draw times, not guessed.
// It starts from the simulated strands alone; over the budget the share shrinks in proportion,
// well under it, it grows (at most doubling a frame); between, it holds (a dead band against
// flicker). Drawn in full when the scene stands still and in every capture
// (app/scene_view.cpp decides when a frame is interactive).
#pragma once

namespace csm {

class InteractiveBudget {
 public:
  // The share (0..1) of the strands beyond the simulated ones to draw in the next interactive
  // frame (DrawAmount::extra).
  float extra() const { return extra_; }
  // After an interactive frame drawn at extra() in `ms` (its passes, measured): the share for the
  // next. budgetMs <= 0: no budget, everything.
  void measured(double ms, double budgetMs);

  // Below this share nothing beyond the simulated strands is drawn.
  static constexpr float kLeast = 1.0f / 64.0f;
  // Grows only under this share of the budget: the band between holds.
  static constexpr double kGrowUnder = 0.75;

 private:
  // From the simulated strands alone: the first frames of a dense groom would otherwise cost
  // what the budget then takes back (on llvmpipe a 100,000-strand groom's first, 2.8 s).
  float extra_ = 0.0f;
};

}  // namespace csm
