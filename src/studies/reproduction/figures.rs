//! The reproduction's figures: the torus pictures of Figures 1–5 and the scan-line
//! figures of one span.

use super::*;

/// Figures 4–5 (the 800-polygon torus by corrected Euler and by Phong, with
/// highlights, frame 37), the diffuse Gouraud render, the difference heat maps with
/// their legends, and the scan-line figures of [`scanline_figures`], each with its file
/// name (in the order of [`outputs`]). The renders follow the experiment's size,
/// scaled up by a whole factor to at least 400 pixels on the shorter side.
///
/// # Errors
/// [`PictureError::Svg`] if a plot fails.
pub fn pictures(exp: &Experiment) -> Result<Vec<(&'static str, Picture)>, PictureError> {
    let k = 400u32.div_ceil(exp.size.0.min(exp.size.1)).max(1);
    let big = Experiment {
        size: (exp.size.0 * k, exp.size.1 * k),
        ..exp.clone()
    };
    let scene = big.scene();
    let mesh = big.mesh(40, 20);
    let frame = render(
        &mesh,
        &scene,
        37,
        RenderOptions {
            exact: false,
            specular: true,
        },
    );
    let look = Look::default();
    let diffuse = Look { ks: 0.0, ..look };
    let phong = Shader::Span(Method::Phong);
    let mut out = Vec::new();
    for (name, m, no_highlights) in RENDERS {
        let l = if no_highlights { diffuse } else { look };
        out.push((name, Picture::Png(shaded_image(&frame, Shader::Span(m), l))));
    }
    for (name, m) in DIFFS {
        out.push((
            name,
            Picture::Png(labelled_difference_image(&frame, Shader::Span(m), phong)),
        ));
    }
    for (name, svg) in scanline_figures(&scene)? {
        out.push((name, Picture::Svg(svg)));
    }
    Ok(out)
}

/// The span of Figures 1–3: unit normals 60° apart in the x–z plane, the scene's
/// light, 100 steps.
pub fn figure_span(scene: &Scene) -> Span<f64> {
    let a = 30f64.to_radians();
    let na = Vec3::new(-a.sin(), 0.0, a.cos());
    let nb = Vec3::new(a.sin(), 0.0, a.cos());
    let l = Vec3::new(
        f64::from(scene.light.x),
        f64::from(scene.light.y),
        f64::from(scene.light.z),
    );
    Span::normalized(na, nb, l, 100).expect("a valid span")
}

/// Figures 1–3 (Phong minus Gouraud, Euler and corrected Euler along
/// [`figure_span`], in 8-bit levels) and the four curves themselves, as SVG texts with
/// their file names.
///
/// # Errors
/// [`PictureError::Svg`] if a plot fails.
pub fn scanline_figures(scene: &Scene) -> Result<Vec<(&'static str, String)>, PictureError> {
    let span = figure_span(scene);
    let values = |m: Method| m.values(&span).expect("span");
    let phong = values(Method::Phong);
    let curve = |m: Method| -> Vec<f64> {
        let v = values(m);
        phong.iter().zip(&v).map(|(p, x)| 255.0 * (p - x)).collect()
    };
    let mut out = Vec::new();
    for (file, title, m, label) in FIGURES {
        out.push((
            file,
            line_plot(title, "difference (8-bit levels)", &[(label, curve(m))])?,
        ));
    }
    let as_levels = |v: Vec<f64>| v.into_iter().map(|x| 255.0 * x).collect::<Vec<_>>();
    out.push((
        CURVES,
        line_plot(
            "One scan line, normals 60° apart",
            "intensity (8-bit levels)",
            &[
                ("Phong", as_levels(phong.clone())),
                ("Gouraud", as_levels(values(Method::Gouraud))),
                ("Euler", as_levels(values(Method::Euler))),
                ("corrected Euler", as_levels(values(Method::PAPER))),
            ],
        )?,
    ));
    Ok(out)
}
