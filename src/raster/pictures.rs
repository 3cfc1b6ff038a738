//! Pictures: PNG renders of a frame, difference heat maps, and SVG plots of one scan
//! line (Figures 1–5 of the paper).

use super::render::{Frame, Shader, COLUMNS};
use image::{Rgb, RgbImage};
use plotters::prelude::*;
use std::path::Path;

/// Lighting of the pictures: `I = K_a + K_d·diffuse + K_s·max(0, N·H)^shininess`.
#[derive(Clone, Copy, Debug)]
pub struct Look {
    /// Ambient term.
    pub ka: f32,
    /// Diffuse weight.
    pub kd: f32,
    /// Specular weight (0 for none).
    pub ks: f32,
    /// Shininess.
    pub shininess: u32,
}

impl Default for Look {
    fn default() -> Self {
        Look {
            ka: 0.08,
            kd: 0.8,
            ks: 0.5,
            shininess: 30,
        }
    }
}

/// An error while writing a picture.
#[derive(Debug, thiserror::Error)]
pub enum PictureError {
    /// The PNG encoder failed.
    #[error("{path}: {source}")]
    Image {
        /// File.
        path: String,
        /// Cause.
        source: image::ImageError,
    },
    /// The plot failed.
    #[error("{path}: {message}")]
    Plot {
        /// File.
        path: String,
        /// Cause.
        message: String,
    },
}

fn column_index(col: Shader) -> usize {
    COLUMNS
        .iter()
        .position(|c| *c == col)
        .expect("a column of COLUMNS")
}

/// The frame as shaded by `col`: its diffuse 8-bit level, plus the specular term by
/// the same method when the frame has one; a warm material on a dark background.
pub fn shaded_image(frame: &Frame, col: Shader, look: Look) -> RgbImage {
    let c = column_index(col);
    let mut img = RgbImage::from_pixel(frame.width, frame.height, Rgb([24, 26, 32]));
    for y in 0..frame.height {
        for x in 0..frame.width {
            let idx = (y * frame.width + x) as usize;
            let Some(l) = frame.levels[c][idx] else {
                continue;
            };
            let d = f32::from(l) / 255.0;
            let s = if frame.specular.is_empty() {
                0.0
            } else {
                look.ks * crate::specular::power(&frame.specular[c][idx], look.shininess)
            };
            let base = [1.0f32, 0.62, 0.32];
            let px =
                base.map(|b| (255.0 * (look.ka + look.kd * d * b + s)).clamp(0.0, 255.0) as u8);
            img.put_pixel(x, y, Rgb(px));
        }
    }
    img
}

/// A heat map of `|level(col) − level(reference)|`: background dark, 0 grey, 1 yellow,
/// 2 orange, 3 or more red.
pub fn difference_image(frame: &Frame, col: Shader, reference: Shader) -> RgbImage {
    let (c, r) = (column_index(col), column_index(reference));
    let mut img = RgbImage::from_pixel(frame.width, frame.height, Rgb([24, 26, 32]));
    for idx in 0..(frame.width * frame.height) as usize {
        let (Some(a), Some(b)) = (frame.levels[c][idx], frame.levels[r][idx]) else {
            continue;
        };
        let px = match a.abs_diff(b) {
            0 => [90, 90, 96],
            1 => [250, 220, 40],
            2 => [250, 140, 20],
            _ => [230, 30, 30],
        };
        let (x, y) = (idx as u32 % frame.width, idx as u32 / frame.width);
        img.put_pixel(x, y, Rgb(px));
    }
    img
}

/// Saves `img` as PNG.
///
/// # Errors
/// [`PictureError::Image`] naming the file.
pub fn save_png(img: &RgbImage, path: &Path) -> Result<(), PictureError> {
    img.save(path).map_err(|source| PictureError::Image {
        path: path.display().to_string(),
        source,
    })
}

/// Plots the curves `(label, values)` over pixels `0..=n` as an SVG line chart.
///
/// # Errors
/// [`PictureError::Plot`] naming the file.
pub fn line_plot(
    path: &Path,
    title: &str,
    y_label: &str,
    series: &[(&str, Vec<f64>)],
) -> Result<(), PictureError> {
    let err = |e: &dyn std::fmt::Display| PictureError::Plot {
        path: path.display().to_string(),
        message: e.to_string(),
    };
    let n = series.iter().map(|s| s.1.len()).max().unwrap_or(1).max(2) - 1;
    let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
    for (_, v) in series {
        for &y in v {
            lo = lo.min(y);
            hi = hi.max(y);
        }
    }
    if !(lo.is_finite() && hi.is_finite()) {
        return Err(err(&"no finite values to plot"));
    }
    let pad = ((hi - lo) * 0.08).max(1e-6);
    let root = SVGBackend::new(path, (720, 420)).into_drawing_area();
    root.fill(&WHITE).map_err(|e| err(&e))?;
    let mut chart = ChartBuilder::on(&root)
        .caption(title, ("sans-serif", 20))
        .margin(12)
        .x_label_area_size(40)
        .y_label_area_size(70)
        .build_cartesian_2d(0f64..n as f64, (lo - pad)..(hi + pad))
        .map_err(|e| err(&e))?;
    chart
        .configure_mesh()
        .x_desc("pixel i along the scan line")
        .y_desc(y_label)
        .draw()
        .map_err(|e| err(&e))?;
    let colors = [
        RGBColor(200, 40, 40),
        RGBColor(30, 90, 200),
        RGBColor(20, 140, 60),
        RGBColor(120, 60, 160),
    ];
    for (k, (label, v)) in series.iter().enumerate() {
        let color = colors[k % colors.len()];
        chart
            .draw_series(LineSeries::new(
                v.iter().enumerate().map(|(i, &y)| (i as f64, y)),
                color.stroke_width(2),
            ))
            .map_err(|e| err(&e))?
            .label(*label)
            .legend(move |(x, y)| {
                PathElement::new(vec![(x, y), (x + 20, y)], color.stroke_width(2))
            });
    }
    chart
        .configure_series_labels()
        .background_style(WHITE.mix(0.85))
        .border_style(BLACK)
        .draw()
        .map_err(|e| err(&e))?;
    root.present().map_err(|e| err(&e))?;
    Ok(())
}
