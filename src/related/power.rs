//! The specular power `max(0, v)^s` by table look-up, as Bishop & Weimer and Seiler
//! evaluate it after their quadratic (the literature: "a table for the power";
//! the table's size is ours, reconstructed).

/// `x^s` tabulated at `x = j/(size − 1)`, `j = 0..size`, read at the nearest entry.
#[derive(Clone, Debug)]
pub struct PowerTable {
    /// The entries.
    pub values: Vec<f64>,
    /// The shininess `s`.
    pub shininess: u32,
}

impl PowerTable {
    /// The table size used in the comparison: 1024 entries.
    pub const SIZE: usize = 1024;

    /// A table of [`PowerTable::SIZE`] entries for shininess `s`.
    pub fn new(shininess: u32) -> Self {
        let last = (Self::SIZE - 1) as f64;
        let values = (0..Self::SIZE)
            .map(|j| (j as f64 / last).powi(shininess as i32))
            .collect();
        PowerTable { values, shininess }
    }

    /// `v^s` at the nearest table entry; `v ≤ 0` gives 0 and `v ≥ 1` gives 1.
    pub fn lookup(&self, v: f64) -> f64 {
        if v.is_nan() || v <= 0.0 {
            return 0.0;
        }
        let last = self.values.len() - 1;
        let j = (v * last as f64).round().min(last as f64) as usize;
        self.values[j]
    }
}
