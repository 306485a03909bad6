// The hair a config grows, without a solver: the scene's head, the strands simulated (the whole
// groom, or its guides) and, when guides stand for the rest, the strands drawn and how they follow.
// A Simulation grows one and hands it to its solver; a render from a shot's cache
// (app/shot_cache.h) grows the same one and draws its cached frames on it, simulating nothing.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "sim/core/config.h"
#include "sim/core/groom.h"
#include "sim/core/pose.h"
#include "sim/groom/followers.h"
#include "sim/groom/guides.h"
#include "sim/groom/scene_groom.h"
#include "sim/head/head_model.h"
#include "sim/motion/clip.h"

namespace csm {

struct GrownScene {
  std::shared_ptr<const HeadModel> head;
  std::shared_ptr<const Groom> groom = std::make_shared<const Groom>();  // the simulated strands
  std::shared_ptr<const FollowerBinding> followers;  // null when every strand is simulated
  GroomReport report;
  std::shared_ptr<const MotionClip> clip;  // motion.clip, read; null without one
  size_t drawnStrands() const {
    return followers ? followers->drawn.strandCount() : groom->strandCount();
  }
};

// Grows the hair `config` asks for: the head (one that `known` already holds is not read again),
// the groom (sim/groom/scene_groom.h), the guides and their followers, the motion clip. False,
// saying why, when the machine cannot hold the scene or a file cannot be read.
bool growScene(const Config& config, const std::string& baseDir, const HeadModel* known,
               const ImportProgress& progress, GrownScene& out, std::string* error);

// The drawn strands' positions (world, a vec4 a point) from the simulated ones with the body at
// `body`: the followers made on the CPU, or the simulated positions as they are. Returns what
// keeping the followers out of the body's parts took (nothing without them).
FollowerStats drawnPositions(const GrownScene& scene, const std::vector<glm::vec4>& simulated,
                             const BodyPose& body, std::vector<glm::vec4>& out);

// A hash of what the groom is (its strands, rest points, pins, colours, weights and, guided, the
// drawn strands and their binding): two scenes with one hash draw the same cached frames alike.
uint64_t groomHash(const GrownScene& scene);

}  // namespace csm
