// csmhair-follow-floor: the followers' error with perfect guides. Given a groom with every strand
// simulated, at rest and at some frame (both --export-hair of the same scene: frame 0, whose head
// pose is the motion's rest, and the frame), chooses and binds GUIDES guides as a scene does,
// takes the guides' own strands from the frame, makes every follower from them (sim/groom/
// followers.h) and prints how far the followers lie from the same strands simulated: RMS, 99th
// percentile, largest (mm). That is the error no guide motion can bring a guided groom under:
// what the interpolation cannot follow of the whole groom's motion. The head's pose at the frame
// is fitted to the roots (they follow the head rigidly); followers are not pushed out of a head.
//
//   csmhair-follow-floor REST.hair FRAME.hair GUIDES
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include <Eigen/Dense>
#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

#include "sim/groom/cyhair.h"
#include "sim/groom/followers.h"
#include "sim/groom/guides.h"

namespace {

using namespace csm;

// The rigid motion taking the rest roots to the frame's (least squares, Kabsch).
Pose fitHead(const Groom& rest, const Groom& frame) {
  const size_t n = rest.strandCount();
  Eigen::Vector3d a = Eigen::Vector3d::Zero(), b = Eigen::Vector3d::Zero();
  auto root = [](const Groom& g, size_t s) {
    const glm::vec3 p = g.points[g.first[s]];
    return Eigen::Vector3d(p.x, p.y, p.z);
  };
  for (size_t s = 0; s < n; ++s) {
    a += root(rest, s);
    b += root(frame, s);
  }
  a /= double(n);
  b /= double(n);
  Eigen::Matrix3d h = Eigen::Matrix3d::Zero();
  for (size_t s = 0; s < n; ++s) h += (root(rest, s) - a) * (root(frame, s) - b).transpose();
  Eigen::JacobiSVD<Eigen::Matrix3d> svd(h, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Matrix3d d = Eigen::Matrix3d::Identity();
  d(2, 2) = (svd.matrixV() * svd.matrixU().transpose()).determinant() < 0 ? -1.0 : 1.0;
  const Eigen::Matrix3d r = svd.matrixV() * d * svd.matrixU().transpose();
  const Eigen::Quaterniond q(r);
  Pose pose;
  pose.rotation = glm::dquat(q.w(), q.x(), q.y(), q.z());
  const Eigen::Vector3d t = b - r * a;
  pose.translation = glm::dvec3(t.x(), t.y(), t.z());
  return pose;
}

bool read(const char* path, Groom& out) {
  io::GroomReadResult r = io::readCyHair(std::string(path));
  if (!r) {
    std::fprintf(stderr, "csmhair-follow-floor: %s\n", r.error.c_str());
    return false;
  }
  out = std::move(*r.groom);
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 4) {
    std::fprintf(stderr, "usage: csmhair-follow-floor REST.hair FRAME.hair GUIDES\n");
    return 2;
  }
  Groom rest, frame;
  if (!read(argv[1], rest) || !read(argv[2], frame)) return 1;
  if (rest.first != frame.first) {
    std::fprintf(stderr, "csmhair-follow-floor: %s and %s are not the same strands\n", argv[1],
                 argv[2]);
    return 1;
  }
  const size_t guides = std::strtoul(argv[3], nullptr, 10);
  if (guides == 0 || guides >= rest.strandCount()) {
    std::fprintf(stderr, "csmhair-follow-floor: GUIDES must be 1 to %zu\n", rest.strandCount() - 1);
    return 2;
  }
  const FollowerBinding b = bindFollowers(rest, chooseGuides(rest, guides));
  std::vector<glm::vec3> guidePoints;
  for (uint32_t s : b.guideStrand)
    guidePoints.insert(guidePoints.end(), frame.points.begin() + frame.first[s],
                       frame.points.begin() + frame.first[s + 1]);
  std::vector<glm::vec3> drawn;
  makeFollowers(b, guidePoints, fitHead(rest, frame), SceneHead{}, drawn);
  std::vector<char> isGuide(rest.strandCount(), 0);
  for (uint32_t s : b.guideStrand) isGuide[s] = 1;
  std::vector<double> d;
  double sum = 0.0;
  for (size_t s = 0; s < rest.strandCount(); ++s)
    if (!isGuide[s])
      for (uint32_t i = rest.first[s]; i < rest.first[s + 1]; ++i) {
        d.push_back(1e3 * glm::length(drawn[i] - frame.points[i]));
        sum += d.back() * d.back();
      }
  std::sort(d.begin(), d.end());
  std::printf(
      "%zu guides, %zu follower points: RMS %.2f mm, 99th percentile %.2f mm, largest %.1f mm\n",
      guides, d.size(), std::sqrt(sum / double(d.size())), d[d.size() * 99 / 100], d.back());
  return 0;
}
