//! The paper's experiment: each torus rendered over many frames, statistics merged.

use super::render::{render, RenderOptions, Scene, Stats};
use crate::raster::mesh::{paper_tori, torus, Mesh, NormalMode};
use glam::Vec3 as G3;
use rayon::prelude::*;

/// The settings of one run of the experiment.
#[derive(Clone, Debug)]
pub struct Experiment {
    /// Frames per torus (the paper: 200).
    pub frames: u32,
    /// Image width and height.
    pub size: (u32, u32),
    /// Major and tube radius of the torus.
    pub radii: (f32, f32),
    /// Vertex normals.
    pub normals: NormalMode,
    /// How many frames of the 800-polygon torus to check exactly (0 = none).
    pub exact_frames: u32,
    /// The choices the paper does not state beyond size, radii and normals.
    pub setup: Setup,
    /// Render frames `0, s, 2s, …` (`s = frame_stride ≥ 1`): fewer frames spread over
    /// the same rotation, as the calibration search uses.
    pub frame_stride: u32,
}

/// Scene choices the paper leaves open, beside the image size, radii and normals of
/// [`Experiment`]: the tessellation's shape, the light and `K_d`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Setup {
    /// Ring segments per tube segment (2: the quads are near square for `r = 0.4`).
    /// Each paper torus of `P = 2k²` polygons gets `tube = √(P/ring_per_tube)` tube and
    /// `P/tube` ring segments; 1/8, 1/2, 2 and 8 give whole numbers for all four.
    pub ring_per_tube: f32,
    /// Angle between the light and the view direction, in degrees; the light lies
    /// towards the upper left, `(−sin φ/√2, sin φ/√2, cos φ)`.
    pub light_deg: f32,
    /// Diffuse coefficient `K_d`.
    pub kd: f32,
}

impl Default for Setup {
    /// Ring twice the tube, the light `normalize(−1, 1, 2)` (35.26° from the view),
    /// `K_d = 1`.
    fn default() -> Self {
        Setup {
            ring_per_tube: 2.0,
            light_deg: (2.0f32 / 6.0f32.sqrt()).acos().to_degrees(),
            kd: 1.0,
        }
    }
}

impl Setup {
    /// The unit light direction (towards the light, view space).
    pub fn light(&self) -> G3 {
        let (s, c) = self.light_deg.to_radians().sin_cos();
        let h = s / std::f32::consts::SQRT_2;
        G3::new(-h, h, c).normalize()
    }

    /// The four tori as `(polygons, ring, tube)` segments, or `None` if the ratio does
    /// not divide every paper count into whole segments.
    pub fn tori(&self) -> Option<[(u32, u32, u32); 4]> {
        let mut out = paper_tori();
        for t in &mut out {
            let tube = (t.0 as f32 / self.ring_per_tube).sqrt().round() as u32;
            if tube < 3 || t.0 % tube != 0 || t.0 / tube < 3 {
                return None;
            }
            let ring = t.0 / tube;
            if (ring as f32 / tube as f32 - self.ring_per_tube).abs() > 1e-3 * self.ring_per_tube {
                return None;
            }
            *t = (t.0, ring, tube);
        }
        Some(out)
    }
}

impl Default for Experiment {
    fn default() -> Self {
        Experiment {
            frames: 200,
            size: (225, 225),
            radii: (1.0, 0.4),
            normals: NormalMode::Analytic,
            exact_frames: 1,
            setup: Setup::default(),
            frame_stride: 1,
        }
    }
}

/// The measured results for one torus.
#[derive(Clone, Debug)]
pub struct TorusResult {
    /// Polygons.
    pub polygons: u32,
    /// Ring × tube segments.
    pub segments: (u32, u32),
    /// Merged statistics over all frames.
    pub stats: Stats,
}

impl Experiment {
    /// The calibrated scene of `reproduce --fit` (docs/reproduction.md, "Calibration"),
    /// with the paper's 200 frames: a fat torus (R = 1, r = 0.8) of the default
    /// tessellation, the light 45° from the view, 210×210 pixels (about 4.3 million
    /// visible pixels per torus), `K_d = 1`.
    pub fn paper_fit() -> Experiment {
        Experiment {
            size: (210, 210),
            radii: (1.0, 0.8),
            setup: Setup {
                ring_per_tube: 2.0,
                light_deg: 45.0,
                kd: 1.0,
            },
            ..Experiment::default()
        }
    }

    /// The scene for this experiment's image size and radii.
    pub fn scene(&self) -> Scene {
        let mut scene = Scene::new(self.size.0, self.size.1, self.radii.0 + self.radii.1);
        scene.light = self.setup.light();
        scene.kd = self.setup.kd;
        scene
    }

    /// The mesh of a torus with `ring × tube` segments.
    pub fn mesh(&self, ring: u32, tube: u32) -> Mesh {
        torus(ring, tube, self.radii.0, self.radii.1, self.normals)
    }

    /// Runs every torus over every frame (frames in parallel with rayon); `tick` is
    /// called once per finished frame (for a progress bar). The tori are those of
    /// [`Setup::tori`] (the paper's default segments if the ratio does not divide).
    pub fn run(&self, tick: &(dyn Fn() + Sync)) -> Vec<TorusResult> {
        let scene = self.scene();
        self.setup
            .tori()
            .unwrap_or_else(paper_tori)
            .iter()
            .map(|&(polygons, ring, tube)| {
                let mesh = self.mesh(ring, tube);
                let stats = (0..self.frames)
                    .into_par_iter()
                    .map(|f| {
                        let exact = polygons == 800 && f < self.exact_frames;
                        let frame = render(
                            &mesh,
                            &scene,
                            f * self.frame_stride.max(1),
                            RenderOptions {
                                exact,
                                specular: false,
                            },
                        );
                        tick();
                        frame.stats
                    })
                    .reduce(Stats::default, |mut a, b| {
                        a.merge(&b);
                        a
                    });
                TorusResult {
                    polygons,
                    segments: (ring, tube),
                    stats,
                }
            })
            .collect()
    }
}

/// A row of the paper's Table 1.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PaperTable1 {
    /// The torus's polygons.
    pub polygons: u32,
    /// The percentage of scan lines that could have been computed with Gouraud.
    pub percent: f64,
}

/// The paper's Table 1: percentage of scan lines that could use Gouraud.
pub const PAPER_TABLE_1: [PaperTable1; 4] = [
    PaperTable1 {
        polygons: 288,
        percent: 54.9,
    },
    PaperTable1 {
        polygons: 512,
        percent: 69.3,
    },
    PaperTable1 {
        polygons: 800,
        percent: 80.9,
    },
    PaperTable1 {
        polygons: 1152,
        percent: 89.0,
    },
];

/// One method's cell of the paper's Table 2: the mean and the maximum deviation from
/// Phong, in 8-bit levels.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PaperDeviation {
    /// The mean deviation.
    pub mean: f64,
    /// The largest deviation.
    pub max: u32,
}

/// A row of the paper's Table 2.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PaperTable2 {
    /// The torus's polygons.
    pub polygons: u32,
    /// Gouraud.
    pub gouraud: PaperDeviation,
    /// Euler.
    pub euler: PaperDeviation,
    /// Corrected Euler.
    pub corrected_euler: PaperDeviation,
}

const fn row2(polygons: u32, g: (f64, u32), e: (f64, u32), ce: (f64, u32)) -> PaperTable2 {
    PaperTable2 {
        polygons,
        gouraud: PaperDeviation {
            mean: g.0,
            max: g.1,
        },
        euler: PaperDeviation {
            mean: e.0,
            max: e.1,
        },
        corrected_euler: PaperDeviation {
            mean: ce.0,
            max: ce.1,
        },
    }
}

/// The paper's Table 2: per torus, Gouraud's, Euler's and corrected Euler's
/// deviation from Phong.
pub const PAPER_TABLE_2: [PaperTable2; 4] = [
    row2(288, (1.08, 15), (0.75, 21), (0.081, 3)),
    row2(512, (0.60, 9), (0.42, 10), (0.033, 1)),
    row2(800, (0.38, 6), (0.28, 6), (0.016, 1)),
    row2(1152, (0.26, 4), (0.21, 5), (0.009, 1)),
];

impl PaperTable2 {
    /// The row's three methods, each with the shader of its column and a name.
    pub fn methods(&self) -> [(crate::Method, &'static str, PaperDeviation); 3] {
        use crate::Method;
        [
            (Method::Gouraud, "Gouraud", self.gouraud),
            (Method::Euler, "Euler", self.euler),
            (Method::PAPER, "corrected Euler", self.corrected_euler),
        ]
    }
}
