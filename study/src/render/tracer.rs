//! The path tracer: a closed box of ColorChecker walls, two spheres and
//! an RGB-textured back wall, lit by one or two square lights in the
//! ceiling. Lambertian surfaces, next-event estimation to a light chosen
//! uniformly, cosine-weighted bounces, and pbrt-v4's Russian roulette (on the
//! throughput's largest component).
//!
//! One tracer serves every way of carrying colour (the core's
//! [`Carry`]): hero wavelengths, a fitted rule, RGB triples, and grey
//! (one number per surface, no colour work, so that colour's share of the
//! time can be measured). A [`Record`] sees what a path met (its surfaces,
//! and each light it saw with the scalar factor it came with), for the
//! exact colour of the same path.

use crate::carry::Carry;
use speclab::Xyz;

/// The deepest path the tracer follows.
pub const MAX_DEPTH: usize = 16;

/// A direction or point.
pub type V3 = [f64; 3];

fn add(a: V3, b: V3) -> V3 {
    [a[0] + b[0], a[1] + b[1], a[2] + b[2]]
}
fn sub(a: V3, b: V3) -> V3 {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}
fn scale(a: V3, s: f64) -> V3 {
    [a[0] * s, a[1] * s, a[2] * s]
}
fn dot(a: V3, b: V3) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}
fn cross(a: V3, b: V3) -> V3 {
    [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
}
fn normalize(a: V3) -> V3 {
    scale(a, 1.0 / dot(a, a).sqrt())
}

/// What a surface is made of: a patch by index, or the texture's texels.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Material {
    /// Patch `i` (of [`PATCHES`]).
    Patch(usize),
    /// The 8 × 8 checker of textured colours on the back wall.
    Texture,
}

/// The patches a scene's surfaces number first; the texels follow.
pub const PATCHES: usize = 6;
/// The texture's texels: 8 × 8.
pub const TEXELS: usize = 64;

impl Material {
    /// The surface's number among the scene's albedos (the patches, then
    /// the texels), at `texel` for the texture.
    #[inline]
    #[must_use]
    pub fn surface(self, texel: usize) -> usize {
        match self {
            Material::Patch(i) => i,
            Material::Texture => PATCHES + texel,
        }
    }
}

/// A hit: distance, point, normal (facing the ray), material, the texel
/// for a textured surface, and the light square hit, if any.
struct Hit {
    t: f64,
    point: V3,
    normal: V3,
    material: Material,
    texel: usize,
    light: Option<usize>,
}

/// The closed box [0, 1]³ with the camera inside, two spheres, and one or
/// two lights: squares in the ceiling.
#[derive(Clone, Debug, PartialEq)]
pub struct Scene {
    /// `(center, radius, material)`.
    pub spheres: [(V3, f64, Material); 2],
    /// Per wall (floor, ceiling, back, left, right, front): its material.
    pub walls: [Material; 6],
    /// The lights' middles (x, z) in the ceiling.
    pub lights: Vec<[f64; 2]>,
}

/// Half a light's side, m: one square of side 0.3, or two of side 0.2
/// (about the same area).
fn light_half(lights: usize) -> f64 {
    if lights > 1 { 0.1 } else { 0.15 }
}

impl Scene {
    fn hit(&self, origin: V3, dir: V3) -> Option<Hit> {
        let mut best: Option<Hit> = None;
        // Walls: (axis, position, inward normal sign).
        let planes =
            [(1, 0.0, 1.0), (1, 1.0, -1.0), (2, 1.0, -1.0), (0, 0.0, 1.0), (0, 1.0, -1.0), (2, 0.0, 1.0)];
        for (w, &(axis, at, sign)) in planes.iter().enumerate() {
            if dir[axis] == 0.0 {
                continue;
            }
            let t = (at - origin[axis]) / dir[axis];
            if t <= 1e-9 || best.as_ref().is_some_and(|b| t >= b.t) {
                continue;
            }
            let p = add(origin, scale(dir, t));
            let inside = (0..3).all(|i| i == axis || (-1e-9..=1.0 + 1e-9).contains(&p[i]));
            if !inside {
                continue;
            }
            let mut normal = [0.0; 3];
            normal[axis] = sign;
            let half = light_half(self.lights.len());
            let light = if w == 1 {
                self.lights.iter().position(|c| (p[0] - c[0]).abs() < half && (p[2] - c[1]).abs() < half)
            } else {
                None
            };
            let texel = ((p[0] * 8.0) as usize).min(7) * 8 + ((p[1] * 8.0) as usize).min(7);
            best = Some(Hit { t, point: p, normal, material: self.walls[w], texel, light });
        }
        for &(center, radius, material) in &self.spheres {
            let oc = sub(origin, center);
            let (b, c) = (dot(oc, dir), dot(oc, oc) - radius * radius);
            let disc = b * b - c;
            if disc < 0.0 {
                continue;
            }
            let t = -b - disc.sqrt();
            if t <= 1e-9 || best.as_ref().is_some_and(|h| t >= h.t) {
                continue;
            }
            let p = add(origin, scale(dir, t));
            let normal = scale(sub(p, center), 1.0 / radius);
            best = Some(Hit { t, point: p, normal, material, texel: 0, light: None });
        }
        best
    }

    /// True if nothing lies between `a` and `b`.
    fn visible(&self, a: V3, b: V3) -> bool {
        let d = sub(b, a);
        let length = dot(d, d).sqrt();
        self.hit(a, scale(d, 1.0 / length)).is_none_or(|h| h.t >= length - 1e-6)
    }
}

/// What a path met, for its exact colour: the surfaces in order, and each
/// light seen after `depth` of them with the scalar factor (geometry and
/// Russian roulette) its contribution carries.
pub trait Record {
    /// The path met surface `surface` (the patches, then the texels).
    fn surface(&mut self, surface: usize);
    /// The path saw light `light` after `depth` surfaces, through a scalar
    /// factor `factor`.
    fn light(&mut self, light: usize, depth: usize, factor: f64);
}

/// Recording nothing: the timed runs.
impl Record for () {
    #[inline(always)]
    fn surface(&mut self, _: usize) {}
    #[inline(always)]
    fn light(&mut self, _: usize, _: usize, _: f64) {}
}

/// A small, fast generator for the geometry (xorshift64*).
#[derive(Clone, Copy, Debug)]
pub struct Rng(pub u64);

impl Rng {
    /// A uniform number in [0, 1).
    pub fn uniform(&mut self) -> f64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        (self.0.wrapping_mul(0x2545_F491_4F6C_DD1D) >> 11) as f64 * (1.0 / (1u64 << 53) as f64)
    }
}

/// A cosine-weighted direction about `n`.
fn cosine(n: V3, rng: &mut Rng) -> V3 {
    let (r, phi) = (rng.uniform().sqrt(), 2.0 * std::f64::consts::PI * rng.uniform());
    let (x, y, z) = (r * phi.cos(), r * phi.sin(), (1.0 - r * r).max(0.0).sqrt());
    let helper = if n[0].abs() > 0.5 { [0.0, 1.0, 0.0] } else { [1.0, 0.0, 0.0] };
    let (t, b) = (normalize(cross(helper, n)), cross(n, normalize(cross(helper, n))));
    add(add(scale(t, x), scale(b, y)), scale(n, z))
}

/// Where a path's light goes: each light's contribution through a
/// throughput, times a scalar factor.
pub trait Sink<P: Carry> {
    /// Light `light` seen through throughput `beta`, times `factor`.
    fn emitted(&mut self, paint: &P, path: &P::Path, light: usize, beta: P::Value, factor: f64);
}

/// The XYZ of what a path's lights gave (the renders' sink).
impl<P: Carry> Sink<P> for Xyz {
    #[inline(always)]
    fn emitted(&mut self, paint: &P, path: &P::Path, light: usize, beta: P::Value, factor: f64) {
        *self += paint.emitted(path, light, beta) * factor;
    }
}

/// One camera path through `(x, y)` in [0, 1]² of the image: its XYZ and
/// the number of surfaces it met; what it met goes to `record`.
pub fn trace<P: Carry>(
    scene: &Scene,
    paint: &P,
    path: &P::Path,
    at: (f64, f64),
    rng: &mut Rng,
    record: &mut impl Record,
) -> (Xyz, u32) {
    let mut radiance = Xyz::ZERO;
    let vertices = trace_into(scene, paint, path, at, rng, record, &mut radiance);
    (radiance, vertices)
}

/// [`trace`], what the lights give going to `sink`; the number of
/// surfaces met.
pub fn trace_into<P: Carry>(
    scene: &Scene,
    paint: &P,
    path: &P::Path,
    (x, y): (f64, f64),
    rng: &mut Rng,
    record: &mut impl Record,
    sink: &mut impl Sink<P>,
) -> u32 {
    let (origin, mut dir) = ([0.5, 0.5, 0.02], normalize([x - 0.5, 0.5 - y, 0.72]));
    let mut origin = origin;
    let (mut beta, mut vertices) = (paint.one(), 0);
    // The scalar part of beta (Russian roulette's 1/q), for the record.
    let mut factor = 1.0;
    let (count, half) = (scene.lights.len(), light_half(scene.lights.len()));
    for depth in 0..MAX_DEPTH {
        let Some(hit) = scene.hit(origin, dir) else { break };
        vertices += 1;
        if let Some(light) = hit.light {
            if depth == 0 {
                sink.emitted(paint, path, light, beta, 1.0);
                record.light(light, 0, 1.0);
            }
            break;
        }
        let surface = hit.material.surface(hit.texel);
        let albedo = paint.albedo(path, surface);
        record.surface(surface);
        let n = if dot(hit.normal, dir) > 0.0 { scale(hit.normal, -1.0) } else { hit.normal };
        // Next-event estimation: a light chosen uniformly (one number only
        // when there are several), a point on it.
        let light = if count > 1 { ((rng.uniform() * count as f64) as usize).min(count - 1) } else { 0 };
        let at = scene.lights[light];
        let on_light =
            [at[0] + half * (2.0 * rng.uniform() - 1.0), 1.0, at[1] + half * (2.0 * rng.uniform() - 1.0)];
        let to_light = sub(on_light, hit.point);
        let d2 = dot(to_light, to_light);
        let w = scale(to_light, 1.0 / d2.sqrt());
        let (cos_surface, cos_light) = (dot(n, w), w[1]);
        if cos_surface > 0.0 && cos_light > 0.0 && scene.visible(add(hit.point, scale(n, 1e-6)), on_light) {
            let area = 4.0 * half * half;
            let geometry = count as f64 * cos_surface * cos_light * area / (std::f64::consts::PI * d2);
            sink.emitted(paint, path, light, beta * albedo, geometry);
            record.light(light, depth + 1, factor * geometry);
        }
        beta *= albedo;
        // Russian roulette as pbrt-v4's: after the second bounce, end the
        // path with probability 1 − max β (the largest component over the
        // wavelengths or channels), and divide a survivor's β by max β.
        if depth >= 2 {
            let survival = paint.max_component(path, beta);
            if survival < 1.0 {
                if rng.uniform() >= survival {
                    break;
                }
                beta = paint.scale(beta, 1.0 / survival);
                factor /= survival;
            }
        }
        origin = add(hit.point, scale(n, 1e-6));
        dir = cosine(n, rng);
    }
    vertices
}
