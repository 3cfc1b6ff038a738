//! The one vector-path dispatch (`simd::dispatch`) from the batched row set-up's
//! side: `Batch::set_up` on every path this CPU has, each of its lanes a different row
//! (position and length), is `Field::row` of that lane's row bit for bit, on every path.

use phong_approx::fast_rows::{Batch, Field, BATCH};
use phong_approx::simd::{self, Path};

macro_rules! batch_on_every_path {
    ($name:ident, $f:ident) => {
        #[test]
        fn $name() {
            let unit = |v: [f64; 3]| {
                let r = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
                v.map(|x| (x / r) as $f)
            };
            let f = Field::<$f>::new(
                [0.033, -0.004, -0.004],
                [-0.002, 0.031, -0.006],
                unit([0.10, 0.05, 1.0]),
                unit([-0.4, 0.4, 0.8]),
            );
            // Eight different rows: positions and lengths differ lane by lane.
            let x: [$f; BATCH] = std::array::from_fn(|r| r as $f * 1.25 - 3.0);
            let y: [$f; BATCH] = std::array::from_fn(|r| 2.0 + (r * r) as $f * 0.5);
            let n: [u32; BATCH] = std::array::from_fn(|r| [0, 1, 3, 7, 8, 31, 64, 129][r]);
            let chosen = simd::path();
            let paths = Path::supported_paths();
            for &path in &paths {
                simd::force(path).unwrap();
                let lanes = Batch::<$f>::set_up(&f, &x, &y, &n);
                for r in 0..BATCH {
                    assert_eq!(
                        lanes.get(r),
                        f.row(x[r], y[r], n[r]),
                        "{} lane {r} on the {path} path",
                        stringify!($f)
                    );
                }
            }
            simd::force(chosen).unwrap();
            assert!(paths.contains(&Path::Baseline));
        }
    };
}

batch_on_every_path!(batch_set_up_is_each_lanes_row_on_every_path_f32, f32);
batch_on_every_path!(batch_set_up_is_each_lanes_row_on_every_path_f64, f64);
