//! Pictures: PNG renders of a frame, difference heat maps, and SVG plots of one scan
//! line (Figures 1–5 of the paper).

use super::render::{index, Frame, Shader};
use super::text;
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
    #[error("plot '{title}': {message}")]
    Svg {
        /// The plot's title.
        title: String,
        /// Cause.
        message: String,
    },
}

/// The frame as shaded by `col`: its diffuse 8-bit level, plus the specular term by
/// the same method when the frame has one; a warm material on a dark background.
pub fn shaded_image(frame: &Frame, col: Shader, look: Look) -> RgbImage {
    let c = index(col);
    let mut img = RgbImage::from_pixel(frame.width, frame.height, BACKGROUND);
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

/// The background of every picture: where no polygon is drawn, and the label strips.
pub const BACKGROUND: Rgb<u8> = Rgb([24, 26, 32]);

/// The colour of the labels on [`BACKGROUND`].
pub const INK: Rgb<u8> = Rgb([235, 235, 235]);

/// The classes of the heat maps' colour scale: the label on the colour bar and the
/// smallest difference (in 8-bit levels) of the class; the last class is open.
pub const HEAT_CLASSES: [(&str, u32); 4] = [("0", 0), ("1", 1), ("2", 2), ("≥3", 3)];

/// The heat-map colour of a difference of `d` 8-bit levels: 0 grey, 1 yellow,
/// 2 orange, 3 or more red.
pub fn heat_colour(d: u32) -> Rgb<u8> {
    Rgb(match d {
        0 => [90, 90, 96],
        1 => [250, 220, 40],
        2 => [250, 140, 20],
        _ => [230, 30, 30],
    })
}

/// A heat map of `|levels − reference|` over a `width × height` picture (both slices
/// row by row, `None` where nothing is drawn): [`heat_colour`] where both have a
/// level, [`BACKGROUND`] elsewhere. Also returns the largest difference (0 for none).
///
/// # Panics
/// If a slice is shorter than `width × height`.
pub fn heat_map(
    width: u32,
    height: u32,
    levels: &[Option<u8>],
    reference: &[Option<u8>],
) -> (RgbImage, u32) {
    let n = (width * height) as usize;
    let mut img = RgbImage::from_pixel(width, height, BACKGROUND);
    let mut max = 0;
    for (idx, (a, b)) in levels[..n].iter().zip(&reference[..n]).enumerate() {
        let (Some(a), Some(b)) = (a, b) else {
            continue;
        };
        let d = u32::from(a.abs_diff(*b));
        max = max.max(d);
        img.put_pixel(idx as u32 % width, idx as u32 / width, heat_colour(d));
    }
    (img, max)
}

/// A heat map of `|level(col) − level(reference)|` ([`heat_map`], colours
/// [`heat_colour`]), without a legend.
pub fn difference_image(frame: &Frame, col: Shader, reference: Shader) -> RgbImage {
    let (c, r) = (index(col), index(reference));
    heat_map(
        frame.width,
        frame.height,
        &frame.levels[c],
        &frame.levels[r],
    )
    .0
}

/// [`difference_image`] with its legend below ([`with_heat_legend`]): the caption
/// `|level − <reference> level|, max <m>` and `method: <col>`, in the columns' table
/// labels, and the colour bar.
pub fn labelled_difference_image(frame: &Frame, col: Shader, reference: Shader) -> RgbImage {
    let (c, r) = (index(col), index(reference));
    let (map, max) = heat_map(
        frame.width,
        frame.height,
        &frame.levels[c],
        &frame.levels[r],
    );
    with_heat_legend(
        &map,
        &[
            format!("|level − {} level|, max {max}", reference.label()),
            format!("method: {}", col.label()),
        ],
    )
}

/// A picture of 8-bit levels (row by row, `None` where nothing is drawn): a warm
/// material, level 255 the colour (255, 235, 200), on [`BACKGROUND`].
///
/// # Panics
/// If `levels` is shorter than `width × height`.
pub fn level_image(width: u32, height: u32, levels: &[Option<u8>]) -> RgbImage {
    let mut img = RgbImage::from_pixel(width, height, BACKGROUND);
    for (idx, l) in levels[..(width * height) as usize].iter().enumerate() {
        if let Some(l) = l {
            let v = f32::from(*l) / 255.0;
            let px = [(255.0 * v) as u8, (235.0 * v) as u8, (200.0 * v) as u8];
            img.put_pixel(idx as u32 % width, idx as u32 / width, Rgb(px));
        }
    }
    img
}

/// The text scale (2 or 1) for `lines` in a strip `width` pixels wide with margins of
/// 4·scale: 2 when every line, and a row `extra(scale)` pixels wide, fits at 2.
pub fn fitting_scale(width: u32, lines: &[String], extra: impl Fn(u32) -> u32) -> u32 {
    let fits = |s: u32| {
        let room = width.saturating_sub(2 * 4 * s);
        lines.iter().all(|l| text::text_width(l, s) <= room) && extra(s) <= room
    };
    if fits(2) {
        2
    } else {
        1
    }
}

/// `lines` with every line longer than `width` pixels at `scale` broken at spaces
/// (a word longer than the width stays whole, and is clipped when drawn).
pub fn wrap(lines: &[String], width: u32, scale: u32) -> Vec<String> {
    let mut out = Vec::new();
    for line in lines {
        let mut cur = String::new();
        for word in line.split(' ') {
            let next = if cur.is_empty() {
                word.to_string()
            } else {
                format!("{cur} {word}")
            };
            if text::text_width(&next, scale) <= width || cur.is_empty() {
                cur = next;
            } else {
                out.push(std::mem::replace(&mut cur, word.to_string()));
            }
        }
        out.push(cur);
    }
    out
}

/// A strip `width` wide of [`BACKGROUND`] with `lines` of text in [`INK`] at `scale`
/// (left-aligned, a margin of 4·`scale` pixels all round, long lines [`wrap`]ped).
pub fn text_strip(width: u32, lines: &[String], scale: u32) -> RgbImage {
    let m = 4 * scale;
    let lines = wrap(lines, width.saturating_sub(2 * m), scale);
    let h = 2 * m + text::lines_height(lines.len() as u32, scale);
    let mut img = RgbImage::from_pixel(width, h, BACKGROUND);
    let m = i64::from(m);
    text::draw_text(&mut img, m, m, &lines.join("\n"), INK, scale);
    img
}

/// The label after the colour bar.
const BAR_UNIT: &str = "8-bit levels";

/// The legend of a heat map, `width` wide: the `caption` lines, then the colour bar
/// (one swatch per class of [`HEAT_CLASSES`], its label below) followed by
/// "8-bit levels". Text at scale 2 where it fits, else 1.
pub fn heat_legend(width: u32, caption: &[String]) -> RgbImage {
    let swatch = |s: u32| 4 * text::ADVANCE * s;
    let bar_row = |s: u32| {
        HEAT_CLASSES.len() as u32 * swatch(s) + text::ADVANCE * s + text::text_width(BAR_UNIT, s)
    };
    let s = fitting_scale(width, caption, bar_row);
    let m = 4 * s;
    let top = text_strip(width, caption, s);
    let bar_h = 5 * s;
    let h = bar_h + 2 * s + text::text_height(s) + m;
    let mut bar = RgbImage::from_pixel(width, h, BACKGROUND);
    for (k, (label, d)) in HEAT_CLASSES.iter().enumerate() {
        let x0 = m + k as u32 * swatch(s);
        for y in 0..bar_h {
            for x in x0..(x0 + swatch(s)).min(width) {
                bar.put_pixel(x, y, heat_colour(*d));
            }
        }
        let lx = x0 + (swatch(s).saturating_sub(text::text_width(label, s))) / 2;
        text::draw_text(
            &mut bar,
            i64::from(lx),
            i64::from(bar_h + 2 * s),
            label,
            INK,
            s,
        );
    }
    let ux = m + HEAT_CLASSES.len() as u32 * swatch(s) + text::ADVANCE * s;
    text::draw_text(&mut bar, i64::from(ux), 0, BAR_UNIT, INK, s);
    stack(&[&top, &bar])
}

/// `map` with its [`heat_legend`] (as wide as the map) below.
pub fn with_heat_legend(map: &RgbImage, caption: &[String]) -> RgbImage {
    stack(&[map, &heat_legend(map.width(), caption)])
}

/// The pictures one above the other, left-aligned, as wide as the widest, the rest
/// [`BACKGROUND`].
pub fn stack(parts: &[&RgbImage]) -> RgbImage {
    let w = parts.iter().map(|p| p.width()).max().unwrap_or(0);
    let h = parts.iter().map(|p| p.height()).sum();
    let mut img = RgbImage::from_pixel(w, h, BACKGROUND);
    let mut y = 0;
    for p in parts {
        image::imageops::replace(&mut img, *p, 0, i64::from(y));
        y += p.height();
    }
    img
}

/// A picture to be written: a raster image (PNG) or an SVG document.
#[derive(Clone, Debug)]
pub enum Picture {
    /// Saved with [`save_png`].
    Png(RgbImage),
    /// The text of an SVG file.
    Svg(String),
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

/// The size of [`line_plot`]'s charts in SVG pixels.
pub const PLOT_SIZE: (u32, u32) = (720, 420);

/// Plots the curves `(label, values)` over pixels `0..=n` as an SVG line chart of
/// [`PLOT_SIZE`]: the title, the x axis "pixel i along the scan line (pixels, n = …)",
/// the y axis `y_label` (which should give the unit), and a legend naming each series
/// in the top-right corner, in a band kept free of the curves (the y range is
/// extended upwards for it), so that it never hides them. Returns the SVG text; the
/// text is `<text>` elements, drawn with the viewer's sans-serif font.
///
/// # Errors
/// [`PictureError::Svg`] naming the title: no finite value to plot, or the plotting
/// library's own failure.
pub fn line_plot(
    title: &str,
    y_label: &str,
    series: &[(&str, Vec<f64>)],
) -> Result<String, PictureError> {
    let err = |e: &dyn std::fmt::Display| PictureError::Svg {
        title: title.to_string(),
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
    // The plotting area is about 330 pixels high; the legend takes about 15 pixels a
    // series plus 15, and sits 10 below the top: that share of the range stays free.
    let band = (15.0 * series.len() as f64 + 35.0) / 330.0;
    let top = lo - pad + (hi - lo + 2.0 * pad) / (1.0 - band);
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, PLOT_SIZE).into_drawing_area();
        root.fill(&WHITE).map_err(|e| err(&e))?;
        let mut chart = ChartBuilder::on(&root)
            .caption(title, ("sans-serif", 20))
            .margin(12)
            .x_label_area_size(40)
            .y_label_area_size(70)
            .build_cartesian_2d(0f64..n as f64, (lo - pad)..top)
            .map_err(|e| err(&e))?;
        chart
            .configure_mesh()
            .x_desc(format!("pixel i along the scan line (pixels, n = {n})"))
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
            .position(SeriesLabelPosition::UpperRight)
            .background_style(WHITE.mix(0.85))
            .border_style(BLACK)
            .draw()
            .map_err(|e| err(&e))?;
        root.present().map_err(|e| err(&e))?;
    }
    Ok(svg)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn heat_colours_grey_for_zero_and_red_from_three_on() {
        assert_eq!(heat_colour(0), Rgb([90, 90, 96]));
        assert_eq!(heat_colour(1), Rgb([250, 220, 40]));
        assert_eq!(heat_colour(2), Rgb([250, 140, 20]));
        for d in [3, 4, 255, u32::MAX] {
            assert_eq!(heat_colour(d), Rgb([230, 30, 30]));
        }
        // The colour bar's classes are the colours' classes.
        for (k, (_, d)) in HEAT_CLASSES.iter().enumerate() {
            assert_eq!(*d, k as u32);
        }
    }

    #[test]
    fn heat_map_colours_where_both_are_drawn_and_reports_the_max() {
        let a = [Some(10), Some(12), None, Some(0), Some(200)];
        let b = [Some(10), Some(10), Some(3), None, Some(190)];
        let (img, max) = heat_map(5, 1, &a, &b);
        assert_eq!(max, 10);
        let px: Vec<Rgb<u8>> = img.pixels().copied().collect();
        assert_eq!(
            px,
            [
                heat_colour(0),
                heat_colour(2),
                BACKGROUND,
                BACKGROUND,
                heat_colour(10)
            ]
        );
        let (_, none) = heat_map(1, 1, &[None], &[None]);
        assert_eq!(none, 0);
    }

    #[test]
    fn level_image_is_dark_where_nothing_is_drawn() {
        let img = level_image(3, 1, &[None, Some(0), Some(255)]);
        assert_eq!(*img.get_pixel(0, 0), BACKGROUND);
        assert_eq!(*img.get_pixel(1, 0), Rgb([0, 0, 0]));
        assert_eq!(*img.get_pixel(2, 0), Rgb([255, 235, 200]));
    }

    #[test]
    fn the_legend_shows_every_colour_and_the_caption() {
        let caption = ["|level − phong level|, max 2".to_string()];
        let map = RgbImage::from_pixel(400, 300, BACKGROUND);
        let img = with_heat_legend(&map, &caption);
        assert_eq!(img.width(), 400);
        assert!(img.height() > 300);
        let legend: Vec<Rgb<u8>> = (300..img.height())
            .flat_map(|y| (0..400).map(move |x| (x, y)))
            .map(|(x, y)| *img.get_pixel(x, y))
            .collect();
        for (_, d) in HEAT_CLASSES {
            assert!(legend.contains(&heat_colour(d)), "class {d}");
        }
        assert!(legend.contains(&INK));
        // The caption fits at scale 2 in 400 pixels: the legend is the strip of the
        // caption, 5·2 pixels of bar, 2·2 of gap, the labels, and the margin.
        let strip = text_strip(400, &caption, 2).height();
        assert_eq!(
            img.height() - 300,
            strip + 10 + 4 + text::text_height(2) + 8
        );
    }

    #[test]
    fn a_narrow_legend_falls_back_to_scale_one_and_wraps() {
        let caption = ["a caption much too long for a narrow picture, in many words".to_string()];
        let wide = heat_legend(1000, &caption);
        let narrow = heat_legend(200, &caption);
        assert!(narrow.height() < wide.height() + 20);
        assert_eq!(narrow.width(), 200);
        let lines = wrap(&caption, 200 - 8, 1);
        assert!(lines.len() > 1);
        assert!(lines.iter().all(|l| text::text_width(l, 1) <= 192));
        assert_eq!(lines.join(" "), caption[0]);
    }

    #[test]
    fn stack_is_as_wide_as_the_widest() {
        let a = RgbImage::from_pixel(3, 2, Rgb([1, 2, 3]));
        let b = RgbImage::from_pixel(5, 1, Rgb([4, 5, 6]));
        let s = stack(&[&a, &b]);
        assert_eq!(s.dimensions(), (5, 3));
        assert_eq!(*s.get_pixel(4, 0), BACKGROUND);
        assert_eq!(*s.get_pixel(4, 2), Rgb([4, 5, 6]));
    }

    #[test]
    fn line_plot_names_its_axes_and_series_and_refuses_no_data() {
        let svg = line_plot(
            "T",
            "intensity (8-bit levels)",
            &[("one", vec![0.0, 1.0, 2.0])],
        )
        .expect("a plot");
        assert!(svg.starts_with("<svg width=\"720\" height=\"420\""));
        for text in [
            "\nT\n",
            "\nintensity (8-bit levels)\n",
            "\npixel i along the scan line (pixels, n = 2)\n",
            "\none\n",
        ] {
            assert!(svg.contains(text), "{text:?}");
        }
        let e = line_plot("empty", "y", &[("nan", vec![f64::NAN])]).expect_err("no data");
        assert_eq!(e.to_string(), "plot 'empty': no finite values to plot");
    }
}

/// Helpers shared by the report modules' tests.
#[cfg(test)]
pub(crate) mod tests_support {
    /// A CSV text's header and records, as strings.
    pub(crate) fn csv_rows(text: &str) -> (Vec<String>, Vec<Vec<String>>) {
        let mut r = csv::Reader::from_reader(text.as_bytes());
        let head = r
            .headers()
            .expect("header")
            .iter()
            .map(String::from)
            .collect();
        let rows = r
            .records()
            .map(|rec| rec.expect("a record").iter().map(String::from).collect())
            .collect();
        (head, rows)
    }
}
