#include "view/space_mesh.h"

#include <algorithm>
#include <cmath>

namespace cablefilm {
namespace {

constexpr float kPi = 3.14159265358979f;

Vec3f operator+(Vec3f a, Vec3f b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
Vec3f operator-(Vec3f a, Vec3f b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
Vec3f operator*(float s, Vec3f a) { return {s * a.x, s * a.y, s * a.z}; }
Vec3f operator-(Vec3f a) { return {-a.x, -a.y, -a.z}; }
float Dot(Vec3f a, Vec3f b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
Vec3f Cross(Vec3f a, Vec3f b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
float Length(Vec3f a) { return std::sqrt(Dot(a, a)); }
// a / |a|, or `fallback` for a vector too short to have a direction.
Vec3f Unit(Vec3f a, Vec3f fallback) {
  const float len = Length(a);
  return len > 1e-12f ? (1 / len) * a : fallback;
}
// A unit vector perpendicular to the unit vector t.
Vec3f Perpendicular(Vec3f t) {
  const Vec3f axis = std::fabs(t.x) < 0.9f ? Vec3f{1, 0, 0} : Vec3f{0, 1, 0};
  return Unit(Cross(t, axis), {0, 0, 1});
}

std::uint8_t Byte(float v) {
  return static_cast<std::uint8_t>(std::lround(std::clamp(v, 0.0f, 1.0f) * 255));
}

// Appends vertices of one colour and material.
class Writer {
 public:
  Writer(std::vector<LitVertex>* out, Rgba c, float grid, float shine) : out_(*out) {
    v_.color[0] = Byte(c.r);
    v_.color[1] = Byte(c.g);
    v_.color[2] = Byte(c.b);
    v_.color[3] = Byte(c.a);
    v_.material[0] = grid;
    v_.material[1] = shine;
  }
  void SetColor(Rgba c) {
    v_.color[0] = Byte(c.r);
    v_.color[1] = Byte(c.g);
    v_.color[2] = Byte(c.b);
    v_.color[3] = Byte(c.a);
  }
  void Vertex(Vec3f p, Vec3f n) {
    v_.pos[0] = p.x;
    v_.pos[1] = p.y;
    v_.pos[2] = p.z;
    v_.normal[0] = n.x;
    v_.normal[1] = n.y;
    v_.normal[2] = n.z;
    out_.push_back(v_);
  }
  void Triangle(Vec3f a, Vec3f b, Vec3f c, Vec3f n) {  // flat
    Vertex(a, n);
    Vertex(b, n);
    Vertex(c, n);
  }

 private:
  std::vector<LitVertex>& out_;
  LitVertex v_{};
};

// A band between two rings of `sides` points about centres a and b, the ring directions
// (unit, also the normals) da and db, radii ra and rb; closed around.
void Band(Writer& w, Vec3f a, const Vec3f* da, float ra, Vec3f b, const Vec3f* db, float rb,
          int sides) {
  for (int i = 0; i < sides; ++i) {
    const int n = (i + 1) % sides;
    const Vec3f a0 = a + ra * da[i], a1 = a + ra * da[n];
    const Vec3f b0 = b + rb * db[i], b1 = b + rb * db[n];
    w.Vertex(a0, da[i]);
    w.Vertex(b0, db[i]);
    w.Vertex(b1, db[n]);
    w.Vertex(a0, da[i]);
    w.Vertex(b1, db[n]);
    w.Vertex(a1, da[n]);
  }
}

// A flat disc (fan) of radius r about c facing `normal`, its rim along the unit directions d.
void Disc(Writer& w, Vec3f c, const Vec3f* d, float r, int sides, Vec3f normal) {
  for (int i = 0; i < sides; ++i) w.Triangle(c, c + r * d[(i + 1) % sides], c + r * d[i], normal);
}

// Unit directions around the unit axis t, starting at the unit normal n.
void Around(Vec3f t, Vec3f n, int sides, Vec3f* out) {
  const Vec3f b = Cross(t, n);
  for (int i = 0; i < sides; ++i) {
    const float a = 2 * kPi * i / sides;
    out[i] = std::cos(a) * n + std::sin(a) * b;
  }
}

}  // namespace

void SpaceMesh::Build(const Scene3& scene) {
  opaque_.clear();
  clear_.clear();
  for (const Sheet& s : scene.sheets)
    if (s.color.a >= 1) AddSheet(s);
  for (const Tube& t : scene.tubes) AddTube(t);
  for (const Solid& s : scene.solids) AddSolid(s);
  for (const Sheet& s : scene.sheets)
    if (s.color.a < 1) AddSheet(s);
}

void SpaceMesh::AddTube(const Tube& tube) {
  const std::size_t n = tube.points.size();
  if (n < 2 || tube.colors.empty() || !(tube.radius > 0)) return;
  const std::vector<Vec3f>& p = tube.points;
  // Each segment's direction (a point repeated takes its neighbour's).
  tangents_.assign(n, Vec3f{});
  Vec3f last{0, 0, 0};
  bool any = false;
  for (std::size_t j = 0; j + 1 < n; ++j) {
    const Vec3f d = p[j + 1] - p[j];
    if (Length(d) > 1e-9f) {
      last = Unit(d, last);
      if (!any)
        for (std::size_t i = 0; i < j; ++i) tangents_[i] = last;
      any = true;
    }
    tangents_[j] = last;
  }
  if (!any) return;  // every point at one place: nothing to draw
  tangents_[n - 1] = tangents_[n - 2];
  // Each ring in the plane halving the bend, wider by 1 / cos(half the bend) so that the tube
  // keeps its width through it; its frame carried along without twist.
  const int sides = kTubeSides;
  ring_.resize(n * sides);
  ring_scale_.resize(n);
  Vec3f normal{};
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3f in = i > 0 ? tangents_[i - 1] : tangents_[0];
    const Vec3f out = i + 1 < n ? tangents_[i] : tangents_[n - 2];
    const Vec3f t = Unit(in + out, out);
    ring_scale_[i] = 1 / std::max(0.5f, Dot(t, out));
    normal = i == 0 ? Perpendicular(t) : Unit(normal - Dot(normal, t) * t, Perpendicular(t));
    Around(t, normal, sides, &ring_[i * sides]);
  }
  const bool clear = tube.colors.front().a < 1;
  Writer w(clear ? &clear_ : &opaque_, tube.colors.front(), 0, 0.35f);
  const bool each = tube.colors.size() + 1 == n;
  for (std::size_t j = 0; j + 1 < n; ++j) {
    if (each) w.SetColor(tube.colors[j]);
    Band(w, p[j], &ring_[j * sides], tube.radius * ring_scale_[j], p[j + 1],
         &ring_[(j + 1) * sides], tube.radius * ring_scale_[j + 1], sides);
  }
  w.SetColor(tube.colors.front());
  Disc(w, p[0], &ring_[0], tube.radius * ring_scale_[0], sides, -tangents_[0]);
  w.SetColor(tube.colors.back());
  // The end cap faces along the tube: its fan runs the other way round.
  const Vec3f* last_ring = &ring_[(n - 1) * sides];
  for (int i = 0; i < sides; ++i)
    w.Triangle(p[n - 1], p[n - 1] + tube.radius * ring_scale_[n - 1] * last_ring[i],
               p[n - 1] + tube.radius * ring_scale_[n - 1] * last_ring[(i + 1) % sides],
               tangents_[n - 2]);
}

void SpaceMesh::AddSolid(const Solid& s) {
  Writer w(s.color.a < 1 ? &clear_ : &opaque_, s.color, 0, 0.45f);
  const Vec3f c = s.centre;
  const float r = s.size;
  switch (s.kind) {
    case SolidKind::kSphere: {
      constexpr int kAround = 16, kRings = 10;
      auto at = [&](int ring, int i) {
        const float lat = kPi * ring / kRings - kPi / 2, lon = 2 * kPi * i / kAround;
        return Vec3f{std::cos(lat) * std::cos(lon), std::sin(lat), std::cos(lat) * std::sin(lon)};
      };
      for (int ring = 0; ring < kRings; ++ring)
        for (int i = 0; i < kAround; ++i) {
          const Vec3f a = at(ring, i), b = at(ring, i + 1), d = at(ring + 1, i + 1),
                      e = at(ring + 1, i);
          w.Vertex(c + r * a, a);
          w.Vertex(c + r * e, e);
          w.Vertex(c + r * d, d);
          w.Vertex(c + r * a, a);
          w.Vertex(c + r * d, d);
          w.Vertex(c + r * b, b);
        }
      break;
    }
    case SolidKind::kBox: {
      const Vec3f axes[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
      for (int a = 0; a < 3; ++a)
        for (float sign : {-1.0f, 1.0f}) {
          const Vec3f n = sign * axes[a], u = axes[(a + 1) % 3], v = axes[(a + 2) % 3];
          const Vec3f m = c + r * n;
          const Vec3f q[4] = {m - r * u - r * v, m + r * u - r * v, m + r * u + r * v,
                              m - r * u + r * v};
          w.Triangle(q[0], q[1], q[2], n);
          w.Triangle(q[0], q[2], q[3], n);
        }
      break;
    }
    case SolidKind::kOctahedron: {
      for (float sx : {-1.0f, 1.0f})
        for (float sy : {-1.0f, 1.0f})
          for (float sz : {-1.0f, 1.0f}) {
            const Vec3f n = Unit({sx, sy, sz}, {0, 1, 0});
            w.Triangle(c + Vec3f{sx * r, 0, 0}, c + Vec3f{0, sy * r, 0}, c + Vec3f{0, 0, sz * r}, n);
          }
      break;
    }
    case SolidKind::kArrow: {
      const float length = Length(s.axis);
      if (!(length > 0)) break;
      constexpr int kSides = 12;
      const Vec3f t = (1 / length) * s.axis;
      const float head = std::min(0.4f * length, 5.0f * r), head_r = 2.4f * r;
      Vec3f d[kSides];
      Around(t, Perpendicular(t), kSides, d);
      const Vec3f neck = c + (length - head) * t, tip = c + s.axis;
      Band(w, c, d, r, neck, d, r, kSides);
      Disc(w, c, d, r, kSides, -t);
      Disc(w, neck, d, head_r, kSides, -t);
      for (int i = 0; i < kSides; ++i) {  // the cone: normals across its slant
        const int j = (i + 1) % kSides;
        const Vec3f ni = Unit(head * d[i] + head_r * t, t), nj = Unit(head * d[j] + head_r * t, t);
        w.Vertex(neck + head_r * d[i], ni);
        w.Vertex(tip, Unit(ni + nj, t));
        w.Vertex(neck + head_r * d[j], nj);
      }
      break;
    }
  }
}

void SpaceMesh::AddSheet(const Sheet& s) {
  const int nu = std::max(2, s.nu), nv = std::max(2, s.nv);
  const bool raised = s.height.size() == static_cast<std::size_t>(nu) * nv;
  grid_.resize(static_cast<std::size_t>(nu) * nv);
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) {
      Vec3f q = s.origin + static_cast<float>(i) * s.du + static_cast<float>(j) * s.dv;
      if (raised) q.y += s.height[i + static_cast<std::size_t>(nu) * j];
      grid_[i + static_cast<std::size_t>(nu) * j] = q;
    }
  auto at = [&](int i, int j) { return grid_[i + static_cast<std::size_t>(nu) * j]; };
  auto normal = [&](int i, int j) {  // across the neighbours; +y for a flat sheet along x, z
    const Vec3f du = at(std::min(i + 1, nu - 1), j) - at(std::max(i - 1, 0), j);
    const Vec3f dv = at(i, std::min(j + 1, nv - 1)) - at(i, std::max(j - 1, 0));
    return Unit(Cross(dv, du), {0, 1, 0});
  };
  Writer w(s.color.a < 1 ? &clear_ : &opaque_, s.color, s.grid, s.shine);
  for (int j = 0; j + 1 < nv; ++j)
    for (int i = 0; i + 1 < nu; ++i) {
      w.Vertex(at(i, j), normal(i, j));
      w.Vertex(at(i + 1, j), normal(i + 1, j));
      w.Vertex(at(i + 1, j + 1), normal(i + 1, j + 1));
      w.Vertex(at(i, j), normal(i, j));
      w.Vertex(at(i + 1, j + 1), normal(i + 1, j + 1));
      w.Vertex(at(i, j + 1), normal(i, j + 1));
    }
}

}  // namespace cablefilm
