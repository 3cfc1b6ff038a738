//! The paper's experiment: each torus rendered over many frames, statistics merged.

use super::mesh::{paper_tori, torus, Mesh, NormalMode};
use super::render::{render, RenderOptions, Scene, Stats};
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
}

impl Default for Experiment {
    fn default() -> Self {
        Experiment {
            frames: 200,
            size: (225, 225),
            radii: (1.0, 0.4),
            normals: NormalMode::Analytic,
            exact_frames: 1,
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
    /// The scene for this experiment's image size and radii.
    pub fn scene(&self) -> Scene {
        Scene::new(self.size.0, self.size.1, self.radii.0 + self.radii.1)
    }

    /// The mesh of a torus with `ring × tube` segments.
    pub fn mesh(&self, ring: u32, tube: u32) -> Mesh {
        torus(ring, tube, self.radii.0, self.radii.1, self.normals)
    }

    /// Runs every torus over every frame (frames in parallel with rayon); `tick` is
    /// called once per finished frame (for a progress bar).
    pub fn run(&self, tick: &(dyn Fn() + Sync)) -> Vec<TorusResult> {
        let scene = self.scene();
        paper_tori()
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
                            f,
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

/// The paper's Table 1: percentage of scan lines that could use Gouraud.
pub const PAPER_TABLE_1: [(u32, f64); 4] = [(288, 54.9), (512, 69.3), (800, 80.9), (1152, 89.0)];

/// The paper's Table 2: (polygons, Gouraud dev, max, Euler dev, max, corrected Euler
/// dev, max).
pub const PAPER_TABLE_2: [(u32, f64, u32, f64, u32, f64, u32); 4] = [
    (288, 1.08, 15, 0.75, 21, 0.081, 3),
    (512, 0.60, 9, 0.42, 10, 0.033, 1),
    (800, 0.38, 6, 0.28, 6, 0.016, 1),
    (1152, 0.26, 4, 0.21, 5, 0.009, 1),
];
