#include "sim/run/grown_scene.h"

#include "sim/base/fnv.h"
#include "sim/run/scene_checks.h"

namespace csm {

bool growScene(const Config& config, const std::string& baseDir, const HeadModel* known,
               const ImportProgress& progress, GrownScene& out, std::string* error) {
  const std::string capacity = checkCapacity(config);
  if (!capacity.empty()) {
    if (error) *error = capacity;
    return false;
  }
  // The scene's head, once: the solver, the generator and the renderer share it.
  std::string headError;
  std::shared_ptr<const HeadModel> head = HeadModel::build(config, &headError, known);
  if (!head) {
    if (error) *error = headError;
    return false;
  }
  std::shared_ptr<const MotionClip> clip;
  if (!config.motion.clip.empty()) {
    clip = MotionClip::load(config.motion, baseDir, glm::dvec3(config.head.pivot), error);
    if (!clip) return false;
  }
  Groom groom;
  GroomReport report;
  if (!buildGroom(config, *head, baseDir, groom, error, &report, progress)) return false;
  // A project's collision spheres, where the preset asks for spheres: the head is made of them,
  // and the groom placed again as the fit placed it, its roots snapped to them.
  if (!report.fileSpheres.empty() && config.collision.headShape == HeadShape::Spheres) {
    Config onSpheres = config;
    onSpheres.head.spheres = report.fileSpheres;
    onSpheres.head.fitSpheres = false;
    onSpheres.hairstyle.importScale = report.fit.scale;
    onSpheres.hairstyle.importOffset = report.fit.translation;
    onSpheres.hairstyle.importPlace = ImportPlace::Fit;
    head = HeadModel::build(onSpheres, &headError, head.get());
    if (!head) {
      if (error) *error = headError;
      return false;
    }
    const std::vector<Sphere> spheres = report.fileSpheres;
    if (!buildGroom(onSpheres, *head, baseDir, groom, error, &report, progress)) return false;
    report.fileSpheres = spheres;
  }
  // The guides, when fewer than every strand are simulated: the followers are bound once here.
  // The file's own guides (a project's, with its follow hairs) when hairstyle.guides is -1.
  std::shared_ptr<const FollowerBinding> followers;
  const bool fileGuides = !report.fileGuides.empty() && config.hairstyle.guides < 0;
  const size_t guides = fileGuides ? report.fileGuides.size()
                                   : guideCount(config.hairstyle.guides, groom.strandCount());
  if (guides < groom.strandCount()) {
    if (progress) progress("choosing guides", 1.0);
    std::vector<uint32_t> chosen = fileGuides ? report.fileGuides : chooseGuides(groom, guides);
    followers =
        std::make_shared<const FollowerBinding>(bindFollowers(std::move(groom), std::move(chosen)));
    groom = followers->guideGroom();
  }
  out.head = std::move(head);
  out.groom = std::make_shared<const Groom>(std::move(groom));
  out.followers = std::move(followers);
  out.report = report;
  out.clip = std::move(clip);
  return true;
}

FollowerStats drawnPositions(const GrownScene& scene, const std::vector<glm::vec4>& simulated,
                             const BodyPose& body, std::vector<glm::vec4>& out) {
  if (!scene.followers) {
    out = simulated;
    return {};
  }
  std::vector<glm::vec3> guides(simulated.size()), drawn;
  for (size_t i = 0; i < simulated.size(); ++i) guides[i] = glm::vec3(simulated[i]);
  const FollowerStats stats =
      makeFollowers(*scene.followers, guides, body, scene.head->collider(), drawn);
  out.resize(drawn.size());
  for (size_t i = 0; i < drawn.size(); ++i) out[i] = glm::vec4(drawn[i], 1.0f);
  return stats;
}

namespace {

// FNV-1a over the bytes of each array in turn (and its length, so that two arrays cannot trade
// elements).
class Hash {
 public:
  template <class T>
  void add(const std::vector<T>& values) {
    const uint64_t n = values.size();
    h_ = fnv1a(&n, sizeof n, h_);
    if (!values.empty()) h_ = fnv1a(values.data(), values.size() * sizeof(T), h_);
  }
  uint64_t value() const { return h_; }

 private:
  uint64_t h_ = kFnv1aOffset;
};

void addGroom(Hash& h, const Groom& g) {
  h.add(g.first);
  h.add(g.points);
  h.add(g.color);
  h.add(g.thickness);
  h.add(g.tipHeld);
  h.add(g.weight);
}

}  // namespace

uint64_t groomHash(const GrownScene& scene) {
  Hash h;
  addGroom(h, *scene.groom);
  if (scene.followers) {
    addGroom(h, scene.followers->drawn);
    h.add(scene.followers->guideStrand);
    h.add(scene.followers->guides);
    h.add(scene.followers->weights);
    h.add(scene.followers->share);
  }
  return h.value();
}

}  // namespace csm
