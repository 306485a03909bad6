// The GPU solver's parameters for a frame: one SimParams block filled by what each part sets (the
// step, the head, the contacts, the volume) and a Substep a step (sim/gpu/gpu_params.h), uploaded
// and bound with every buffer at its point of shaders/sim/bindings.glsl.
#include <cmath>
#include <cstring>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

#include "sim/gpu/buffer_fill.h"
#include "sim/gpu/gpu_solver.h"
#include "sim/solver/contacts.h"
#include "shaders/sim/bindings.glsl"

namespace csm {

void GpuSolver::writeParams(const std::vector<Pose>& poses, const std::vector<Pose>& before,
                            const std::vector<Pose>& torso, const std::vector<Pose>& torsoBefore) {
  writeStepParams(params_);
  writeHeadParams(params_);
  writeContactParams(params_, poses.back());
  volume_.writeParams(params_, config_.collision, head_);
  const std::vector<Pose> still(poses.size(), torso_);
  uploadParams(poses, before, torso.empty() ? still : torso,
               torsoBefore.empty() ? still : torsoBefore);
}

void GpuSolver::writeStepParams(gpu::SimParams& p) const {
  const SimConfig& sim = config_.sim;
  const WindConfig& wind = config_.wind;
  p.gravity = sim.gravity;
  const glm::dvec3 dir = glm::normalize(glm::dvec3(wind.direction));
  p.windDirection = glm::vec3(dir);
  p.windStrength = wind.strength;
  p.gusts = wind.gusts;
  p.gustFrequency = wind.gustFrequency;
  p.turbulence = wind.turbulence;
  p.turbulenceScale = wind.turbulenceScale;
  p.alpha = sim.stiffness;
  p.strainLimit = sim.strainLimit;
  p.dftl = dftlOf(config_);
  p.windDrag = wind.drag;
  static_assert(int(StiffnessModel::Paper) == CSM_STIFFNESS_PAPER &&
                int(StiffnessModel::Calibrated) == CSM_STIFFNESS_CALIBRATED);
  p.stiffnessModel = int(sim.stiffnessModel);
  p.rotationIterations = sim.rotationIterations;
  p.strainLimiting = sim.strainLimiting;
  p.windOn = wind.strength > 0.0f && wind.drag > 0.0f;
  p.particles = hair_.particles;
  p.strands = hair_.strands;
  p.segments = hair_.segments;
}

void GpuSolver::writeHeadParams(gpu::SimParams& p) const {
  const CollisionConfig& col = config_.collision;
  p.radius = col.radius;
  p.headFriction = col.headFriction;
  p.headSpheres = int(shape_.spheres.size() + shape_.torsoSpheres.size());
  p.torsoSphereFirst = int(shape_.spheres.size());
  p.headCollision = collidesWithHead(col.mode);
  if (const DistanceGrid* field = uploadedField_) {
    p.headFieldOrigin = field->origin;
    p.headFieldCell = field->cell;
    p.headFieldDims = glm::uvec3(field->dims);
    p.headIsField = 1u;
  } else {
    p.headFieldOrigin = glm::vec3(0.0f);
    p.headFieldCell = 1.0f;
    p.headFieldDims = glm::uvec3(2u);
    p.headIsField = 0u;
  }
  if (const DistanceGrid* torso = uploadedTorso_) {
    p.torsoFieldOrigin = torso->origin;
    p.torsoFieldCell = torso->cell;
    p.torsoFieldDims = glm::uvec3(torso->dims);
    p.torsoFieldOffset = uint32_t(uploadedField_->nodes.size());
    p.torsoIsField = 1u;
  } else {
    p.torsoFieldOrigin = glm::vec3(0.0f);
    p.torsoFieldCell = 1.0f;
    p.torsoFieldDims = glm::uvec3(2u);
    p.torsoFieldOffset = 0u;
    p.torsoIsField = 0u;
  }
}

void GpuSolver::writeContactParams(gpu::SimParams& p, const Pose& frameEnd) const {
  const CollisionConfig& col = config_.collision;
  const float radius = float(contactRadius(col, meanWeight_));
  const float reach = 2.0f * radius + col.margin;
  p.contactRadius = radius;
  p.candidateDistance = reach;
  p.compliance = col.compliance;
  p.friction = col.friction;
  p.sweepSolve = col.solve == ContactSolve::Sweep ? 1.0f : 0.0f;
  // The strain limit's sweep applies the constraints' corrections; penalties go to velocities.
  p.strandContacts = strandContacts(col.mode) && col.model == ContactModel::Constraints;
  p.penaltyStiffness = col.penaltyStiffness;
  p.penaltyDamping = col.penaltyDamping;
  contactSearch_.writeParams(p, reach);
  // Cells count from the head, so the clamped 10-bit cell coordinates (common.glsl) cover
  // +-512 cells around it wherever it moves.
  p.gridOrigin = glm::vec3(frameEnd.translation);
}

void GpuSolver::uploadParams(const std::vector<Pose>& poses, const std::vector<Pose>& before,
                             const std::vector<Pose>& torso, const std::vector<Pose>& torsoBefore) {
  const SimConfig& sim = config_.sim;
  const gpu::SimParams& p = params_;
  const int substeps = int(poses.size());
  substepsWritten_ = substeps;
  const double h = double(sim.dt) / substeps;
  const double keep = std::exp(-double(sim.damping) * h);
  std::vector<unsigned char> blob(sizeof(gpu::SimParams) + substeps * sizeof(gpu::Substep));
  std::memcpy(blob.data(), &p, sizeof(p));
  std::vector<glm::vec4> spheres;
  double t = time_;
  for (int k = 0; k < substeps; ++k) {
    gpu::Substep s;
    s.head = poses[k].matrix();
    // Where a point on the head at the end of the step was at its start (head friction),
    // composed in double: before * inverse(now).
    glm::dmat4 now = glm::mat4_cast(poses[k].rotation), was = glm::mat4_cast(before[k].rotation);
    now[3] = glm::dvec4(poses[k].translation, 1.0);
    was[3] = glm::dvec4(before[k].translation, 1.0);
    s.headDelta = glm::mat4(was * glm::inverse(now));
    // The torso's pose, and its delta as a rotation and a translation, composed in double.
    const Pose& body = torso[size_t(k)];
    const Pose delta = compose(torsoBefore[size_t(k)], inverse(body));
    s.torsoRotation = glm::vec4(body.rotation.x, body.rotation.y, body.rotation.z, body.rotation.w);
    s.torsoTranslation = glm::vec4(glm::vec3(body.translation), 0.0f);
    s.torsoDeltaRotation =
        glm::vec4(delta.rotation.x, delta.rotation.y, delta.rotation.z, delta.rotation.w);
    s.torsoDeltaTranslation = glm::vec4(glm::vec3(delta.translation), 0.0f);
    s.stepStart = float(t);
    s.h = float(h);
    s.twistStep = float(twistStepOf(sim, h, sim.rotationIterations));
    s.velocityKept = float(keep);
    std::memcpy(blob.data() + sizeof(p) + k * sizeof(s), &s, sizeof(s));
    for (const Sphere& sp : worldSpheres(shape_.spheres, poses[k]))
      spheres.emplace_back(sp.center, sp.radius);
    for (const Sphere& sp : worldSpheres(shape_.torsoSpheres, torso[size_t(k)]))
      spheres.emplace_back(sp.center, sp.radius);
    t += h;  // as CpuSolver advances its clock, step by step
  }
  if (reads_.uniformParams) {
    // A uniform block is read whole: the buffer holds CSM_MAX_SUBSTEPS steps, used or not.
    if (size_t(paramsBuffer_.size()) < gpu::kParamBlockBytes)
      paramsBuffer_.setData(GLsizeiptr(gpu::kParamBlockBytes), nullptr,
                            gl::BufferUsage::DynamicDraw);
    paramsBuffer_.setSubData(0, GLsizeiptr(blob.size()), blob.data());
  } else {
    paramsBuffer_.upload(blob);
  }
  gpu::fill(spheres_, spheres);
}

void GpuSolver::bindAll() {
  const gl::BufferTarget ssbo = gl::BufferTarget::ShaderStorage;
  hair_.bind();
  contactSearch_.bind();
  contactSolve_.bind();
  paramsBuffer_.bindBase(ssbo, CSM_BIND_PARAMS);
  if (reads_.uniformParams) paramsBuffer_.bindBase(gl::BufferTarget::Uniform, CSM_UNIFORM_PARAMS);
  volume_.bind();
  headFieldTex_.bind(CSM_TEX_HEAD_FIELD);
  headField_.bindBase(ssbo, CSM_BIND_HEAD_FIELD);
  spheres_.bindBase(ssbo, CSM_BIND_SPHERES);
  measure_.bindBase(ssbo, CSM_BIND_MEASURE);
}

}  // namespace csm
