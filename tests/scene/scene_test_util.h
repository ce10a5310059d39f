// Helpers shared by the scene tests: the default camera, projection and ray casting.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <optional>
#include <string>
#include <vector>

#include "scene/scene.h"

namespace taa::scene::testing {

// Base64 of `d`, for glTF buffers written inline as data URIs.
inline std::string base64(const std::vector<uint8_t>& d) {
  static const char* a = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (size_t i = 0; i < d.size(); i += 3) {
    uint32_t v = uint32_t(d[i]) << 16;
    if (i + 1 < d.size()) v |= uint32_t(d[i + 1]) << 8;
    if (i + 2 < d.size()) v |= uint32_t(d[i + 2]);
    out += a[(v >> 18) & 63];
    out += a[(v >> 12) & 63];
    out += i + 1 < d.size() ? a[(v >> 6) & 63] : '=';
    out += i + 2 < d.size() ? a[v & 63] : '=';
  }
  return out;
}

inline std::filesystem::path assetPath(const std::string& name) {
  return std::filesystem::path(TAA_SOURCE_DIR) / "cases" / "scenes" / name;
}

// The case defaults: (0, 1.6, 6) looking at (0, 0.5, 0), 60 degrees vertical, 320x180.
struct DefaultCamera {
  glm::vec3 eye{0.0f, 1.6f, 6.0f};
  glm::vec3 forward = glm::normalize(glm::vec3(0.0f, 0.5f, 0.0f) - eye);
  glm::vec3 right = glm::normalize(glm::cross(forward, glm::vec3(0.0f, 1.0f, 0.0f)));
  glm::vec3 up = glm::cross(right, forward);
  float tanHalfY = std::tan(glm::radians(30.0f));
  float width = 320.0f, height = 180.0f;
  float aspect = 16.0f / 9.0f;
  // Focal length in pixels: a width w at view depth z covers w * focal / z pixels.
  float focal() const { return 0.5f * height / tanHalfY; }

  float depth(const glm::vec3& p) const { return glm::dot(p - eye, forward); }
  // Pixel coordinates (x right, y down) of a point in front of the camera.
  glm::vec2 project(const glm::vec3& p) const {
    const glm::vec3 d = p - eye;
    const float z = glm::dot(d, forward);
    return {0.5f * width + focal() * glm::dot(d, right) / z,
            0.5f * height - focal() * glm::dot(d, up) / z};
  }
  bool inView(const glm::vec3& p, float marginPx = 0.0f) const {
    if (depth(p) < 0.1f) return false;
    const glm::vec2 s = project(p);
    return s.x >= -marginPx && s.x <= width + marginPx && s.y >= -marginPx &&
           s.y <= height + marginPx;
  }
  glm::vec3 ray(float px, float py) const {
    const float x = (2.0f * px / width - 1.0f) * tanHalfY * aspect;
    const float y = (1.0f - 2.0f * py / height) * tanHalfY;
    return glm::normalize(forward + right * x + up * y);
  }
};

// A model's triangles posed at time 0, in world space: posed once, cast at by many rays.
inline std::vector<std::array<glm::vec3, 3>> posedTriangles(const Scene& scene, int model) {
  std::vector<std::array<glm::vec3, 3>> out;
  for (const MeshDraw& draw : poseModel(scene, model, 0.0))
    for (const Primitive& p : scene.meshes[size_t(draw.mesh)].primitives)
      for (uint32_t i = 0; i + 2 < p.indexCount; i += 3) {
        auto& v = out.emplace_back();
        for (int k = 0; k < 3; ++k) {
          const uint32_t idx =
              scene.indices[p.firstIndex + i + uint32_t(k)] + uint32_t(p.vertexOffset);
          v[size_t(k)] = glm::vec3(draw.transform * glm::vec4(scene.vertices[idx].position, 1.0f));
        }
      }
  return out;
}

// Nearest hit distance of a ray with posed triangles (alpha ignored).
inline std::optional<float> castRay(const std::vector<std::array<glm::vec3, 3>>& triangles,
                                    const glm::vec3& o, const glm::vec3& d) {
  std::optional<float> best;
  for (const auto& v : triangles) {
    // Moller-Trumbore, both sides.
    const glm::vec3 e1 = v[1] - v[0], e2 = v[2] - v[0], pv = glm::cross(d, e2);
    const float det = glm::dot(e1, pv);
    if (std::fabs(det) < 1e-12f) continue;
    const glm::vec3 tv = o - v[0];
    const float u = glm::dot(tv, pv) / det;
    if (u < 0.0f || u > 1.0f) continue;
    const glm::vec3 qv = glm::cross(tv, e1);
    const float w = glm::dot(d, qv) / det;
    if (w < 0.0f || u + w > 1.0f) continue;
    const float t = glm::dot(e2, qv) / det;
    if (t > 1e-4f && (!best || t < *best)) best = t;
  }
  return best;
}

}  // namespace taa::scene::testing
