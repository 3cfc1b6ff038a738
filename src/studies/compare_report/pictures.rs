//! The comparison's pictures: each torus's methods side by side in a labelled grid.

use super::*;

/// The highlight figures [`pictures`] writes besides [`GRID`]: Figures 4 and 5
/// (corrected Euler and Phong) at every shininess of [`SHININESS`].
pub fn picture_names() -> Vec<String> {
    SHININESS
        .iter()
        .flat_map(|sv| {
            ["fig4_corrected_euler", "fig5_phong"].map(|name| format!("{name}_s{sv}.png"))
        })
        .collect()
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
                skip_study: false,
            },
        );
        if *sv == 50 {
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
