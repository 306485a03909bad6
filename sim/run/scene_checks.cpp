#include "sim/run/scene_checks.h"

#include <unistd.h>

#include <glm/geometric.hpp>

namespace csm {

std::vector<std::string> crossCheck(const Config& c) {
  std::vector<std::string> e;
  const HairstyleConfig& h = c.hairstyle;
  if (h.minParticles > h.maxParticles)
    e.push_back("hairstyle.min_particles: " + std::to_string(h.minParticles) +
                " is greater than hairstyle.max_particles " + std::to_string(h.maxParticles));
  if (h.lengthMin > h.lengthMax)
    e.push_back("hairstyle.length_min: " + std::to_string(h.lengthMin) +
                " is greater than hairstyle.length_max " + std::to_string(h.lengthMax));
  if (h.particlesPerStrand != 0 && h.particlesPerStrand < 3)
    e.push_back("hairstyle.particles_per_strand: " + std::to_string(h.particlesPerStrand) +
                " is too few; use 0 (by length) or at least 3");
  if (c.sim.pinned >= (h.particlesPerStrand ? h.particlesPerStrand : h.minParticles))
    e.push_back("sim.pinned: " + std::to_string(c.sim.pinned) +
                " pins every particle of the shortest strand");
  if (glm::length(c.wind.direction) < 1e-6f && c.wind.strength > 0.0f)
    e.push_back("wind.direction: must not be zero when wind.strength is above 0");
  return e;
}

std::string checkCapacity(const Config& c) {
  const HairstyleConfig& h = c.hairstyle;
  // A groom file's size is checked by its reader (sim/io) before anything is allocated.
  if (!h.file.empty()) return {};
  const uint64_t perStrand = h.particlesPerStrand > 0 ? h.particlesPerStrand : h.maxParticles;
  const uint64_t particles = uint64_t(h.strands) * perStrand;
  // The CPU reference holds about 400 bytes a particle (double state, prefix sums, grid);
  // the GPU solver about 200 bytes of buffers.
  const uint64_t bytes = particles * 400;
  const uint64_t pages = static_cast<uint64_t>(sysconf(_SC_PHYS_PAGES));
  const uint64_t pageSize = static_cast<uint64_t>(sysconf(_SC_PAGE_SIZE));
  const uint64_t memory = pages * pageSize;
  if (particles > (1ull << 27))
    return "hairstyle.strands: " + std::to_string(h.strands) + " strands of up to " +
           std::to_string(perStrand) + " particles (" + std::to_string(particles) +
           " particles) exceed the limit of 134217728 particles";
  if (memory > 0 && bytes > memory / 2)
    return "hairstyle.strands: " + std::to_string(h.strands) + " strands of up to " +
           std::to_string(perStrand) + " particles need about " + std::to_string(bytes >> 20) +
           " MiB, more than half of this machine's " + std::to_string(memory >> 20) + " MiB";
  return {};
}

}  // namespace csm
