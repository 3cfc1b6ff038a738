//! The comparison's pictures: each torus's methods side by side in a labelled grid.

use super::*;
use crate::studies::compare::{SKIP_SHININESS, SQUARED_FIGURE_SHININESS, SQUARED_METHODS};

/// The highlight figures [`pictures`] writes besides [`GRID`]: Figures 4 and 5
/// (corrected Euler and Phong) at every shininess of [`SHININESS`].
pub fn picture_names() -> Vec<String> {
    SHININESS
        .iter()
        .flat_map(|sv| {
            ["fig4_corrected_euler", "fig5_phong"].map(|name| format!("{name}_s{sv}.png"))
        })
        .chain([SKIP_MAP.to_string(), SQUARED_MAP.to_string()])
        .collect()
}

/// The squared method's specular difference from Phong's ([`squared_figure`]).
pub const SQUARED_MAP: &str = "squared_specular.png";

/// The labelled heat maps of `|level − Phong's level|` of the specular term at
/// [`SQUARED_FIGURE_SHININESS`], one per method of [`SQUARED_METHODS`] side by side at
/// twice the frame's size, each labelled with its largest difference; the heat maps'
/// legend below, `title` above.
pub fn squared_figure(frame: &CompareFrame, title: &[String]) -> RgbImage {
    let (fw, fh) = (frame.width, frame.height);
    let (w, h) = (2 * fw, 2 * fh);
    let n = (fw * fh) as usize;
    let reference: Vec<Option<u8>> = frame
        .squared_map
        .iter()
        .take(n)
        .map(|l| l.map(|l| l[0]))
        .collect();
    let s = 2;
    let head = text::text_height(s) + 8;
    let mut tiles = RgbImage::from_pixel(3 * w, head + h, BACKGROUND);
    for (k, name) in SQUARED_METHODS.iter().enumerate() {
        let levels: Vec<Option<u8>> = frame
            .squared_map
            .iter()
            .take(n)
            .map(|l| l.map(|l| l[k + 1]))
            .collect();
        let (map, max) = heat_map(fw, fh, &levels, &reference);
        let map = image::imageops::resize(&map, w, h, image::imageops::FilterType::Nearest);
        let x = k as u32 * w;
        let label = text::fit(&format!("{name}: max {max}"), w.saturating_sub(8), s);
        text::draw_text(&mut tiles, i64::from(x + 4), 4, &label, INK, s);
        image::imageops::replace(&mut tiles, &map, i64::from(x), i64::from(head));
    }
    let legend = heat_legend(
        3 * w,
        &[format!(
            "|specular level − Phong's specular level| per pixel at s = {SQUARED_FIGURE_SHININESS}, K_s = 1, in 8-bit levels"
        )],
    );
    let top = text_strip(3 * w, title, fitting_scale(3 * w, title, |_| 0));
    stack(&[&top, &tiles, &legend])
}

/// The map of skipped specular spans ([`skip_figure`]).
pub const SKIP_MAP: &str = "skip_map.png";

/// The skip map's colour of code `c` ([`CompareFrame::skip_map`]): warm where the
/// specular pass must run at a high shininess, cool where it is skipped early.
fn skip_colour(c: u8) -> image::Rgb<u8> {
    const COLOURS: [[u8; 3]; 5] = [
        [255, 214, 64], // shaded even at the largest shininess
        [40, 70, 160],  // skipped from s = 1 on
        [110, 80, 170], // from s = 8
        [200, 70, 120], // from s = 32
        [235, 120, 50], // from s = 128
    ];
    image::Rgb(COLOURS[usize::from(c).min(4)])
}

/// The labelled map of a frame's specular spans: each pixel coloured by the smallest
/// shininess of [`SKIP_SHININESS`] from which Phong's exact test skips its span
/// (`K_s = 1`), drawn at twice the frame's size; a legend of the five colours below,
/// `title` above.
pub fn skip_figure(frame: &CompareFrame, title: &[String]) -> RgbImage {
    let (fw, fh) = (frame.width, frame.height);
    let mut map = RgbImage::from_pixel(fw, fh, BACKGROUND);
    for (idx, c) in frame.skip_map.iter().enumerate().take((fw * fh) as usize) {
        if let Some(c) = c {
            map.put_pixel(idx as u32 % fw, idx as u32 / fw, skip_colour(*c));
        }
    }
    let (w, h) = (2 * fw, 2 * fh);
    let map = image::imageops::resize(&map, w, h, image::imageops::FilterType::Nearest);
    let mut labels = vec![format!(
        "shaded at every s up to {}",
        SKIP_SHININESS[SKIP_SHININESS.len() - 1]
    )];
    labels.extend(
        SKIP_SHININESS
            .iter()
            .map(|s| format!("skipped from s = {s}")),
    );
    labels.push("dark: no span decided (a row of one pixel)".to_string());
    let s = fitting_scale(w, &labels, |_| 0).min(2);
    let line = text::text_height(s) + 2 * s;
    let sw = 3 * text::ADVANCE * s;
    let mut legend = RgbImage::from_pixel(w, 8 * s + line * labels.len() as u32, BACKGROUND);
    for (k, label) in labels.iter().enumerate() {
        let y = 4 * s + k as u32 * line;
        let code = if k == 0 { 0 } else { k as u8 };
        for yy in (y..y + text::text_height(s)).filter(|_| k < 5) {
            for xx in 4 * s..(4 * s + sw).min(w) {
                legend.put_pixel(xx, yy, skip_colour(code));
            }
        }
        let room = w.saturating_sub(sw + 12 * s);
        text::draw_text(
            &mut legend,
            i64::from(sw + 8 * s),
            i64::from(y),
            &text::fit(label, room, s),
            INK,
            s,
        );
    }
    let top = text_strip(w, title, fitting_scale(w, title, |_| 0));
    stack(&[&top, &map, &legend])
}

/// The labelled grid of `frame`: a title (`title`'s lines), then every shader of
/// [`COLUMNS`], four per row, as a pair of pictures — its shading (labelled with
/// its table label) and its heat map against the reference, the first shader
/// (labelled with the largest difference) — and at the bottom the heat maps' legend.
pub fn grid(frame: &CompareFrame, title: &[String]) -> RgbImage {
    let (w, h) = (frame.width, frame.height);
    let per_row = 4u32;
    let n = COLUMNS.len() as u32;
    let rows = n.div_ceil(per_row);
    let width = w * 2 * per_row;
    let longest = COLUMNS.iter().map(|s| s.label()).max_by_key(|l| l.len());
    let s = if text::text_width(longest.as_deref().unwrap_or(""), 2) + 8 <= w {
        2
    } else {
        1
    };
    let head = text::text_height(s) + 8;
    let mut tiles = RgbImage::from_pixel(width, rows * (head + h), BACKGROUND);
    let reference = &frame.picture[0];
    for (c, sh) in COLUMNS.iter().enumerate() {
        let (gx, gy) = (
            (c as u32 % per_row) * 2 * w,
            (c as u32 / per_row) * (head + h),
        );
        let (map, max) = heat_map(w, h, &frame.picture[c], reference);
        let right = if c == 0 {
            "reference".to_string()
        } else {
            format!("max {max}")
        };
        // Each label is cut to its own tile, so that neighbours never overlap.
        let room = w.saturating_sub(8);
        let left = text::fit(&sh.label(), room, s);
        let right = text::fit(&right, room, s);
        text::draw_text(
            &mut tiles,
            i64::from(gx + 4),
            i64::from(gy + 4),
            &left,
            INK,
            s,
        );
        text::draw_text(
            &mut tiles,
            i64::from(gx + w + 4),
            i64::from(gy + 4),
            &right,
            INK,
            s,
        );
        let shaded = level_image(w, h, &frame.picture[c]);
        image::imageops::replace(&mut tiles, &shaded, i64::from(gx), i64::from(gy + head));
        image::imageops::replace(&mut tiles, &map, i64::from(gx + w), i64::from(gy + head));
    }
    let legend = grid_legend(width);
    let top = text_strip(width, title, fitting_scale(width, title, |_| 0));
    stack(&[&top, &tiles, &legend])
}

/// The legend below the grid's tiles, `width` wide.
pub(super) fn grid_legend(width: u32) -> RgbImage {
    let reference = COLUMNS[0].label();
    heat_legend(
        width,
        &[format!(
            "Right of each method: |level − {reference} level| per pixel, in 8-bit levels; above it the largest."
        )],
    )
}

/// The pictures of `compare` at frame `f` of the 800-polygon torus: the labelled
/// [`grid`] at shininess 50, and the highlight figures of [`picture_names`], each
/// with its file name.
pub fn pictures(exp: &Experiment, f: u32) -> Vec<(String, RgbImage)> {
    let scene = exp.scene();
    let mesh = exp.mesh(40, 20);
    let mut out = Vec::new();
    for (k, sv) in SHININESS.iter().enumerate() {
        let frame = render_compare(
            &mesh,
            &scene,
            f,
            CompareOptions {
                pictures: true,
                shininess: k,
                skip_study: *sv == 50,
            },
        );
        if *sv == 50 {
            let title = [
                format!("Specular spans skipped by Phong's exact test: 800-polygon torus, frame {f}, K_s = 1"),
                "Colour: the smallest shininess s from which a span's specular pass is skipped (no pixel of it reaches level 1)".to_string(),
            ];
            out.push((SKIP_MAP.to_string(), skip_figure(&frame, &title)));
            let title = [
                format!("Specular levels against Phong's: 800-polygon torus, frame {f}"),
                "Corrected Euler on (N·H)² (§7.1, question b); on N·H then the power; Duff"
                    .to_string(),
            ];
            out.push((SQUARED_MAP.to_string(), squared_figure(&frame, &title)));
            let title = [
                format!(
                    "Every method on the 800-polygon torus: frame {f}, {}×{} pixels, diffuse + specular (N·H)^{sv}",
                    frame.width, frame.height
                ),
                "Each method: its shading (left, labelled as in the tables) and its difference from the reference (right)".to_string(),
            ];
            out.push((GRID.to_string(), grid(&frame, &title)));
        }
        for (name, label) in [
            ("fig4_corrected_euler", "corrected-euler"),
            ("fig5_phong", "phong-pixel"),
        ] {
            let c = crate::studies::compare::index(shader(label));
            out.push((
                format!("{name}_s{sv}.png"),
                level_image(frame.width, frame.height, &frame.picture[c]),
            ));
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_file_names_are_the_tables_grid_and_highlights() {
        assert_eq!(
            picture_names(),
            [
                "fig4_corrected_euler_s10.png",
                "fig5_phong_s10.png",
                "fig4_corrected_euler_s50.png",
                "fig5_phong_s50.png",
                "fig4_corrected_euler_s200.png",
                "fig5_phong_s200.png",
                "skip_map.png",
                "squared_specular.png"
            ]
        );
    }

    /// The skip map colours each decided pixel by its code and leaves the rest the
    /// background; the legend has a line per colour.
    #[test]
    fn the_skip_map_colours_each_code_and_has_a_legend() {
        let (w, h) = (200u32, 20u32);
        let frame = CompareFrame {
            width: w,
            height: h,
            picture: Vec::new(),
            skip_map: (0..w * h)
                .map(|i| (i % 7 < 5).then_some((i % 7) as u8))
                .collect(),
            squared_map: Vec::new(),
            stats: crate::studies::compare::CompareStats::default(),
        };
        let title = ["title".to_string()];
        let img = skip_figure(&frame, &title);
        let top = text_strip(2 * w, &title, fitting_scale(2 * w, &title, |_| 0)).height();
        for (x, want) in [
            (0, Some(0)),
            (3, Some(3)),
            (4, Some(4)),
            (5, None),
            (6, None),
        ] {
            // Twice the size: pixel x of the frame is 2x and 2x + 1.
            let got = *img.get_pixel(2 * x + 1, top + 1);
            assert_eq!(got, want.map_or(BACKGROUND, skip_colour), "pixel {x}");
        }
        let colours: std::collections::HashSet<_> = (0..5).map(skip_colour).collect();
        assert_eq!(colours.len(), 5);
        assert_eq!(img.width(), 2 * w);
        assert!(img.height() > top + 2 * h + 6 * text::text_height(1));
    }
}

#[cfg(test)]
mod squared_tests {
    use super::*;
    use crate::studies::pictures::heat_colour;

    /// Each panel colours `|level − Phong's|` of its method, and says its largest.
    #[test]
    fn the_squared_figure_has_a_heat_map_per_method() {
        let (w, h) = (60u32, 10u32);
        let frame = CompareFrame {
            width: w,
            height: h,
            picture: Vec::new(),
            skip_map: Vec::new(),
            squared_map: (0..w * h)
                .map(|i| (i >= w).then_some([10, 13, 10, 11]))
                .collect(),
            stats: crate::studies::compare::CompareStats::default(),
        };
        let title = ["title".to_string()];
        let img = squared_figure(&frame, &title);
        assert_eq!(img.width(), 6 * w);
        let top = text_strip(6 * w, &title, fitting_scale(6 * w, &title, |_| 0)).height();
        let y = top + text::text_height(2) + 8 + 2 * h - 1;
        for (k, d) in [3, 0, 1].into_iter().enumerate() {
            assert_eq!(
                *img.get_pixel(k as u32 * 2 * w + 1, y),
                heat_colour(d),
                "panel {k}"
            );
        }
        // The first frame row is not drawn: background.
        assert_eq!(
            *img.get_pixel(1, top + text::text_height(2) + 8),
            BACKGROUND
        );
    }
}
