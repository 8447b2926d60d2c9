//! The render example's box on the GPU: the study's scene (ColorChecker
//! walls and spheres, the RGB-textured back wall through sRGB's table,
//! D65 through a square in the ceiling) traced in WGSL with hero
//! wavelengths, written as a PNG and compared region by region (each wall,
//! sphere and the light) with the CPU tracer's image of the same scene:
//! mean XYZ within 3 standard errors, or an exit status of 1.
//!
//! ```sh
//! cargo run --release -p speclab-gpu --example gpu_box -- --out target/gpu-box.png
//! ```

use std::path::PathBuf;
use std::time::Instant;

use speclab::color::RgbSpace;
use speclab::data::Light;
use speclab::sampling::pdf::{Uniform, WavelengthPdf};
use speclab::spectrum::{DenseObserver, DenseSpectrum, WavelengthRange};
use speclab::{TabulatedSpectrum, Xyz};
use speclab_gpu::{Data, Gpu};
use speclab_study::carry::Hero;
use speclab_study::display::{Exposure, GamutMap, PixelPipeline};
use speclab_study::evaluate::Named;
use speclab_study::render::run::display_white;
use speclab_study::render::tracer::{Material, Scene};
use speclab_study::render::ways::Albedo;
use speclab_study::render::{Options, Setup, render};

/// Image size, GPU paths per pixel, CPU passes and paths per pass.
const SIZE: usize = 64;
const GPU_SPP: u32 = 512;
const PASSES: u64 = 32;
const CPU_SPP: usize = 16;
/// The most paths per pixel in one dispatch. On lavapipe a dispatch of
/// 1,024 or 2,048 paths per pixel ends some pixels' loops early (as few as
/// 814 paths traced, reproducibly; 256 and fewer trace them all): each
/// pixel counts its paths, and a short count is an error.
const DISPATCH_SPP: u32 = 64;

fn main() {
    let out = std::env::args()
        .skip_while(|a| a != "--out")
        .nth(1)
        .map_or("target/gpu-box.png".into(), PathBuf::from);
    match run(&out) {
        Ok(true) => {}
        Ok(false) => std::process::exit(1),
        Err(e) => {
            eprintln!("error: {e}");
            std::process::exit(2);
        }
    }
}

/// Renders on both, writes the PNGs, prints the regions; true if each
/// region agrees within 3 standard errors.
fn run(out: &std::path::Path) -> Result<bool, Box<dyn std::error::Error>> {
    let setup = Setup::new(&[Named::from(Light::D65)])?;
    let gpu = Gpu::new()?;
    println!("adapter: {} ({:?})", gpu.adapter.name, gpu.adapter.device_type);
    let start = Instant::now();
    let (gpu_mean, gpu_var, regions) = gpu_render(&gpu, &setup)?;
    let gpu_seconds = start.elapsed().as_secs_f64();
    let start = Instant::now();
    let passes = cpu_render(&setup)?;
    let cpu_seconds = start.elapsed().as_secs_f64();
    let paths = |spp: f64| (SIZE * SIZE) as f64 * spp;
    println!(
        "GPU: {:.2} s, {:.0} paths/s; CPU (2 threads): {:.2} s, {:.0} paths/s",
        gpu_seconds,
        paths(f64::from(GPU_SPP)) / gpu_seconds,
        cpu_seconds,
        paths((CPU_SPP * PASSES as usize) as f64) / cpu_seconds
    );
    let cpu_mean: Vec<Xyz> =
        (0..SIZE * SIZE).map(|p| passes.iter().map(|r| r[p]).sum::<Xyz>() / PASSES as f64).collect();
    // Both exposed alike: the CPU image's display white (the render example's).
    let white = display_white(&cpu_mean, setup.white);
    write_png(&gpu_mean, white, out)?;
    write_png(&cpu_mean, white, &out.with_extension("cpu.png"))?;
    println!("wrote {} and {}", out.display(), out.with_extension("cpu.png").display());
    Ok(compare(&gpu_mean, &gpu_var, &regions, &passes))
}

/// The GPU's image: each pixel's mean XYZ, the variance of that mean, and
/// the region its centre sees.
type GpuImage = (Vec<Xyz>, Vec<Xyz>, Vec<usize>);

/// [`GpuImage`] of the box, traced on `gpu`.
fn gpu_render(gpu: &Gpu, setup: &Setup) -> Result<GpuImage, Box<dyn std::error::Error>> {
    let space = RgbSpace::srgb();
    let mut spectra: Vec<&TabulatedSpectrum> = vec![&setup.lights[0].spectrum];
    spectra.extend(&setup.patches);
    let spectra: Vec<&dyn speclab::Spectrum> =
        spectra.into_iter().map(|s| s as &dyn speclab::Spectrum).collect();
    let data = Data::new(DenseObserver::ASSIGNMENT, space, &spectra).upload(&gpu.device)?;
    let kernel = speclab_gpu::source(space) + &scene_constants(&setup.scene) + include_str!("gpu_box.wgsl");
    let spp: u32 = std::env::var("GPU_SPP").ok().and_then(|v| v.parse().ok()).unwrap_or(GPU_SPP);
    let n = SIZE * SIZE;
    // Dispatches of at most 256 paths per pixel, summed here (as a
    // renderer's progressive passes).
    let per_dispatch: u32 =
        std::env::var("DISPATCH_SPP").ok().and_then(|v| v.parse().ok()).unwrap_or(DISPATCH_SPP);
    let mut sums = vec![0.0f64; 8 * n];
    for (pass, start) in (0..spp).step_by(per_dispatch.max(1) as usize).enumerate() {
        let mut input = vec![SIZE as u32, SIZE as u32, per_dispatch.min(spp - start), 0x5eed + pass as u32];
        input.extend(setup.colours.iter().flat_map(|c| c.to_array().map(|v| (v as f32).to_bits())));
        let words = gpu.run(&kernel, &data, &input, 8 * n, n as u32)?;
        for (k, (s, w)) in sums.iter_mut().zip(words).enumerate() {
            let v = f64::from(f32::from_bits(w));
            // Word 6 of a pixel is its region, the others sums.
            *s = if k % 8 == 6 { v } else { *s + v };
        }
    }
    let short: Vec<f64> = sums.chunks_exact(8).map(|p| p[7]).filter(|&c| c != f64::from(spp)).collect();
    if let Some(least) = short.iter().copied().reduce(f64::min) {
        return Err(
            format!("{} pixels traced fewer than {spp} paths (as few as {least})", short.len()).into()
        );
    }
    let spp = f64::from(spp);
    let (mut mean, mut var, mut region) = (vec![], vec![], vec![]);
    for p in sums.chunks_exact(8) {
        let m = Xyz::new(p[0], p[1], p[2]) / spp;
        let squares = Xyz::new(p[3], p[4], p[5]) / spp;
        // The variance of the mean of spp paths (the sample variance over spp − 1).
        let v = Xyz::new(squares.x - m.x * m.x, squares.y - m.y * m.y, squares.z - m.z * m.z)
            * (spp / (spp - 1.0))
            / spp;
        mean.push(m);
        var.push(v);
        region.push(p[6] as usize);
    }
    Ok((mean, var, region))
}

/// The scene as WGSL constants: the study's walls (the planes of
/// `tracer::Scene::hit`, floor, ceiling, back, left, right, front), its
/// spheres and light; a patch is spectrum 1 + its index (0 is the light).
fn scene_constants(scene: &Scene) -> String {
    let material = |m: Material| match m {
        Material::Patch(i) => format!("{}u", i + 1),
        Material::Texture => "TEXTURE".into(),
    };
    let list = |items: Vec<String>| items.join(", ");
    let v3 = |v: [f64; 3]| format!("vec3<f32>({:?}, {:?}, {:?})", v[0] as f32, v[1] as f32, v[2] as f32);
    let range = WavelengthRange::ASSIGNMENT;
    let half = if scene.lights.len() > 1 { 0.1 } else { 0.15 };
    let light = scene.lights[0];
    format!(
        "
const SCENE_WALL_AXIS = array<u32, 6>(1u, 1u, 2u, 0u, 0u, 2u);
const SCENE_WALL_AT = array<f32, 6>(0.0, 1.0, 1.0, 0.0, 1.0, 0.0);
const SCENE_WALL_SIGN = array<f32, 6>(1.0, -1.0, -1.0, 1.0, -1.0, 1.0);
const SCENE_WALL_MATERIAL = array<u32, 6>({walls});
const SCENE_SPHERE_CENTRE = array<vec3<f32>, 2>({centres});
const SCENE_SPHERE_RADIUS = array<f32, 2>({radii});
const SCENE_SPHERE_MATERIAL = array<u32, 2>({spheres});
const SCENE_LIGHT = vec2<f32>({lx:?}, {lz:?});
const SCENE_LIGHT_HALF: f32 = {half:?};
const SCENE_OFFSET: u32 = {offset}u;
const SCENE_WIDTH: u32 = {width}u;
",
        walls = list(scene.walls.iter().map(|&m| material(m)).collect()),
        centres = list(scene.spheres.iter().map(|s| v3(s.0)).collect()),
        radii = list(scene.spheres.iter().map(|s| format!("{:?}", s.1 as f32)).collect()),
        spheres = list(scene.spheres.iter().map(|s| material(s.2)).collect()),
        lx = light[0] as f32,
        lz = light[1] as f32,
        offset = (range.min() - 360.0) as u32,
        width = range.width() as u32,
    )
}

/// The CPU tracer on the same scene, hero wavelengths in `f32` over the
/// same dense spectra and table lookups: one image per pass.
fn cpu_render(setup: &Setup) -> Result<Vec<Vec<Xyz>>, speclab::Error> {
    let lights = vec![DenseSpectrum::new(&setup.lights[0].spectrum)];
    let mut surfaces: Vec<Albedo<DenseSpectrum>> =
        setup.patches.iter().map(|p| Albedo::Measured(DenseSpectrum::new(p))).collect();
    surfaces.extend(setup.colours.iter().map(|&c| Albedo::Lookup(c, RgbSpace::srgb())));
    let pdf: Box<dyn WavelengthPdf + Sync> = Box::new(Uniform::ASSIGNMENT);
    let hero = Hero::new(lights, surfaces, DenseObserver::ASSIGNMENT, pdf)?.precision::<f32>();
    let options = Options { width: SIZE, height: SIZE, spp: CPU_SPP, ..Options::default() };
    Ok((0..PASSES).map(|pass| render(setup, &hero, &options, (CPU_SPP, 2), pass + 1, None).xyz).collect())
}

/// Per region: the GPU's and CPU's mean XYZ, their standard errors, and
/// the difference in standard errors; true if every |z| ≤ 3.
fn compare(gpu: &[Xyz], gpu_var: &[Xyz], regions: &[usize], passes: &[Vec<Xyz>]) -> bool {
    let names =
        ["floor", "ceiling", "back (texture)", "left", "right", "front", "sphere 1", "sphere 2", "light"];
    let mut all = true;
    println!("| region | pixels | GPU X, Y, Z | CPU X, Y, Z | z (X, Y, Z) |\n|---|---:|---|---|---|");
    for (r, name) in names.iter().enumerate() {
        let pixels: Vec<usize> = (0..regions.len()).filter(|&p| regions[p] == r).collect();
        if pixels.is_empty() {
            continue;
        }
        let n = pixels.len() as f64;
        let g = pixels.iter().map(|&p| gpu[p]).sum::<Xyz>() / n;
        let g_var = pixels.iter().map(|&p| gpu_var[p]).sum::<Xyz>() / (n * n);
        let per_pass: Vec<Xyz> =
            passes.iter().map(|image| pixels.iter().map(|&p| image[p]).sum::<Xyz>() / n).collect();
        let c = per_pass.iter().copied().sum::<Xyz>() / PASSES as f64;
        let spread = |f: fn(&Xyz) -> f64| {
            per_pass.iter().map(|x| (f(x) - f(&c)).powi(2)).sum::<f64>() / ((PASSES - 1) * PASSES) as f64
        };
        let c_var = Xyz::new(spread(|x| x.x), spread(|x| x.y), spread(|x| x.z));
        let z = |a: f64, b: f64, va: f64, vb: f64| (a - b) / (va + vb).sqrt();
        let zs =
            [z(g.x, c.x, g_var.x, c_var.x), z(g.y, c.y, g_var.y, c_var.y), z(g.z, c.z, g_var.z, c_var.z)];
        all &= zs.iter().all(|z| z.abs() <= 3.0);
        println!(
            "| {name} | {} | {:.4}, {:.4}, {:.4} | {:.4}, {:.4}, {:.4} | {:+.2}, {:+.2}, {:+.2} |",
            pixels.len(),
            g.x,
            g.y,
            g.z,
            c.x,
            c.y,
            c.z,
            zs[0],
            zs[1],
            zs[2]
        );
    }
    println!(
        "{}",
        if all {
            "every region within 3 standard errors"
        } else {
            "a region differs by more than 3 standard errors"
        }
    );
    all
}

/// `xyz` as an sRGB PNG, exposed for the display white `white`.
fn write_png(xyz: &[Xyz], white: Xyz, path: &std::path::Path) -> std::io::Result<()> {
    let pipeline = PixelPipeline::new(Exposure::fit_white(white), GamutMap::Chroma);
    let space = RgbSpace::srgb();
    let rgb = xyz.iter().flat_map(|&x| {
        let p = pipeline.pixel(space.rgb(x));
        [p.r, p.g, p.b]
    });
    let image = speclab_cli::png::Image { width: SIZE, height: SIZE, rgb: rgb.collect() };
    if let Some(dir) = path.parent() {
        std::fs::create_dir_all(dir)?;
    }
    speclab_cli::png::write_file(path, &image)
}
