//! The statistics of Table 2 and of the comparison: per column, the deviation of the
//! 8-bit levels from the reference's over the visible pixels.

/// Per-column accumulators of Table 2.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Deviation {
    /// Visible pixels counted.
    pub pixels: u64,
    /// Sum of |level − Phong level|.
    pub sum: u64,
    /// Maximum |level − Phong level|.
    pub max: u32,
}

impl Deviation {
    /// Mean deviation in 8-bit levels.
    pub fn mean(&self) -> f64 {
        if self.pixels == 0 {
            0.0
        } else {
            self.sum as f64 / self.pixels as f64
        }
    }

    /// Counts one pixel whose level is `a` where the reference's is `b`.
    pub(crate) fn add(&mut self, a: u8, b: u8) {
        let x = u32::from(a.abs_diff(b));
        self.pixels += 1;
        self.sum += u64::from(x);
        self.max = self.max.max(x);
    }

    /// Adds `o` into `self`.
    pub fn merge(&mut self, o: &Deviation) {
        self.pixels += o.pixels;
        self.sum += o.sum;
        self.max = self.max.max(o.max);
    }
}

/// Per column of `levels` (column-major: `levels[c][pixel]`, `None` where nothing is
/// visible), the deviation from column `reference` over the pixels it covers.
///
/// # Panics
/// If a column lacks a pixel the reference has (every column draws the same pixels).
pub fn deviations(levels: &[Vec<Option<u8>>], reference: usize) -> Vec<Deviation> {
    let mut out = vec![Deviation::default(); levels.len()];
    for (idx, r) in levels[reference].iter().enumerate() {
        let Some(r) = *r else { continue };
        for (column, dev) in levels.iter().zip(out.iter_mut()) {
            dev.add(column[idx].expect("every column writes the same pixels"), r);
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn deviation_counts_and_merges() {
        let levels = vec![
            vec![Some(10), None, Some(200)],
            vec![Some(12), None, Some(199)],
        ];
        let d = deviations(&levels, 0);
        assert_eq!(
            d[0],
            Deviation {
                pixels: 2,
                sum: 0,
                max: 0
            }
        );
        assert_eq!(
            d[1],
            Deviation {
                pixels: 2,
                sum: 3,
                max: 2
            }
        );
        assert_eq!(d[1].mean(), 1.5);
        let mut m = d[1].clone();
        m.merge(&d[0]);
        assert_eq!(
            m,
            Deviation {
                pixels: 4,
                sum: 3,
                max: 2
            }
        );
    }
}
