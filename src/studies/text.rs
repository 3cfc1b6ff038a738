//! Text on the raster pictures, in embedded-graphics' 6×10 mono font (ISO 8859-1), so
//! that the pictures carry their own labels without a font file (the `image` crate
//! draws no text, and the machines that build the pictures need not have fonts).
//!
//! embedded-graphics lays the text out and draws its glyphs; this module only gives it
//! a canvas on an [`RgbImage`] at an integer scale (each font pixel a `scale × scale`
//! square, clipped at the image's edges) and maps the few signs the labels use beyond
//! ISO 8859-1 to their ASCII spellings ([`latin1`]), so that no label shows the font's
//! replacement glyph.

use std::borrow::Cow;

use embedded_graphics::{
    mono_font::{iso_8859_1::FONT_6X10, MonoFont, MonoTextStyle},
    pixelcolor::Rgb888,
    prelude::*,
    text::{Baseline, LineHeight, Text, TextStyleBuilder},
};
use image::{Rgb, RgbImage};

/// The font of every label.
pub const FONT: MonoFont<'static> = FONT_6X10;
/// Horizontal advance from one character to the next, in font pixels.
pub const ADVANCE: u32 = FONT.character_size.width + FONT.character_spacing;
/// Height of a line of text in font pixels, descenders included.
pub const GLYPH_HEIGHT: u32 = FONT.character_size.height;
/// Vertical advance from one line to the next, in font pixels (two blank rows).
pub const LINE_HEIGHT: u32 = GLYPH_HEIGHT + 2;

/// `text` in the font's character set: the minus sign and the dashes become `-`, the
/// ellipsis `...`, `≥` and `≤` become `>=` and `<=`; ISO 8859-1 (which has `·`, `°`,
/// `×`) stays as it is. Any other character is the font's replacement glyph.
pub fn latin1(text: &str) -> Cow<'_, str> {
    if text.chars().all(|c| u32::from(c) <= 0xFF) {
        return Cow::Borrowed(text);
    }
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        match c {
            '−' | '–' | '—' => out.push('-'),
            '…' => out.push_str("..."),
            '≥' => out.push_str(">="),
            '≤' => out.push_str("<="),
            c => out.push(c),
        }
    }
    Cow::Owned(out)
}

/// The width in image pixels of `text` drawn on one line at `scale` (0 for empty text).
pub fn text_width(text: &str, scale: u32) -> u32 {
    latin1(text).chars().count() as u32 * ADVANCE * scale
}

/// The height in image pixels of one line of text at `scale`.
pub fn text_height(scale: u32) -> u32 {
    GLYPH_HEIGHT * scale
}

/// The height in image pixels of `lines` lines of text at `scale` (the last line
/// without the gap below it; 0 for none).
pub fn lines_height(lines: u32, scale: u32) -> u32 {
    match lines {
        0 => 0,
        n => ((n - 1) * LINE_HEIGHT + GLYPH_HEIGHT) * scale,
    }
}

/// `text` cut to fit `width` pixels at `scale`: whole if it fits, else as many of its
/// first characters as fit followed by `...` (nothing when even that is too wide).
pub fn fit(text: &str, width: u32, scale: u32) -> String {
    let text = latin1(text);
    if text_width(&text, scale) <= width {
        return text.into_owned();
    }
    let room = (width / (ADVANCE * scale.max(1))) as usize;
    match room.checked_sub(3) {
        Some(keep) => text.chars().take(keep).chain("...".chars()).collect(),
        None => String::new(),
    }
}

/// An [`RgbImage`] seen by embedded-graphics at `scale`: font pixel `(px, py)` is the
/// square at `(x + px·scale, y + py·scale)`, clipped at the image's edges.
struct Canvas<'a> {
    img: &'a mut RgbImage,
    x: i64,
    y: i64,
    scale: i64,
}

impl OriginDimensions for Canvas<'_> {
    fn size(&self) -> Size {
        let s = self.scale.max(1) as u32;
        Size::new(self.img.width().div_ceil(s), self.img.height().div_ceil(s))
    }
}

impl DrawTarget for Canvas<'_> {
    type Color = Rgb888;
    type Error = std::convert::Infallible;

    fn draw_iter<I>(&mut self, pixels: I) -> Result<(), Self::Error>
    where
        I: IntoIterator<Item = Pixel<Self::Color>>,
    {
        let (w, h) = (i64::from(self.img.width()), i64::from(self.img.height()));
        let s = self.scale;
        for Pixel(p, c) in pixels {
            let (px, py) = (self.x + i64::from(p.x) * s, self.y + i64::from(p.y) * s);
            for qy in py.max(0)..(py + s).min(h) {
                for qx in px.max(0)..(px + s).min(w) {
                    self.img
                        .put_pixel(qx as u32, qy as u32, Rgb([c.r(), c.g(), c.b()]));
                }
            }
        }
        Ok(())
    }
}

/// Draws `text` (one line, or several separated by `\n`, [`LINE_HEIGHT`] apart) with
/// the top-left corner of its first glyph cell at `(x, y)`, each font pixel a
/// `scale × scale` square of `colour` (a scale of 0 draws nothing). Only the glyphs'
/// set pixels are drawn, so the background shows between them; whatever falls outside
/// the image is clipped (`x` and `y` may be negative or past the edges).
pub fn draw_text(img: &mut RgbImage, x: i64, y: i64, text: &str, colour: Rgb<u8>, scale: u32) {
    if scale == 0 {
        return;
    }
    let style = MonoTextStyle::new(&FONT, Rgb888::new(colour[0], colour[1], colour[2]));
    let layout = TextStyleBuilder::new()
        .baseline(Baseline::Top)
        .line_height(LineHeight::Pixels(LINE_HEIGHT))
        .build();
    let mut canvas = Canvas {
        img,
        x,
        y,
        scale: i64::from(scale),
    };
    let text = latin1(text);
    let Ok(_) = Text::with_text_style(&text, Point::zero(), style, layout).draw(&mut canvas);
}

#[cfg(test)]
mod tests {
    use super::*;

    const INK: Rgb<u8> = Rgb([0, 0, 0]);
    const PAPER: Rgb<u8> = Rgb([255, 255, 255]);

    fn inked(img: &RgbImage) -> Vec<(u32, u32)> {
        img.enumerate_pixels()
            .filter(|(_, _, p)| **p == INK)
            .map(|(x, y, _)| (x, y))
            .collect()
    }

    #[test]
    fn text_stays_inside_its_measured_box() {
        let text = "Euler n=64 · 3° × 2";
        for scale in 1..=3 {
            let mut img = RgbImage::from_pixel(400, 60, PAPER);
            draw_text(&mut img, 5, 7, text, INK, scale);
            let px = inked(&img);
            assert!(!px.is_empty());
            let (w, h) = (text_width(text, scale), text_height(scale));
            assert!(px
                .iter()
                .all(|&(x, y)| (5..5 + w).contains(&x) && (7..7 + h).contains(&y)));
        }
    }

    #[test]
    fn scale_two_draws_each_font_pixel_as_a_two_by_two_square() {
        let mut one = RgbImage::from_pixel(80, 20, PAPER);
        let mut two = RgbImage::from_pixel(160, 40, PAPER);
        draw_text(&mut one, 0, 0, "Ag9,|", INK, 1);
        draw_text(&mut two, 0, 0, "Ag9,|", INK, 2);
        for (x, y, p) in two.enumerate_pixels() {
            assert_eq!(p, one.get_pixel(x / 2, y / 2), "at ({x}, {y})");
        }
    }

    #[test]
    fn signs_beyond_latin1_draw_as_their_ascii_spelling() {
        for (sign, ascii) in [("−1", "-1"), ("a…", "a..."), ("≥2", ">=2"), ("≤2", "<=2")] {
            let (mut a, mut b) = (
                RgbImage::from_pixel(60, 12, PAPER),
                RgbImage::from_pixel(60, 12, PAPER),
            );
            draw_text(&mut a, 0, 0, sign, INK, 1);
            draw_text(&mut b, 0, 0, ascii, INK, 1);
            assert_eq!(a, b, "{sign}");
            assert_eq!(text_width(sign, 1), text_width(ascii, 1));
        }
        assert!(latin1("3° × 2 · 1").chars().all(|c| u32::from(c) <= 0xFF));
    }

    #[test]
    fn lines_advance_by_the_line_height() {
        let mut two = RgbImage::from_pixel(20, 40, PAPER);
        let mut one = RgbImage::from_pixel(20, 40, PAPER);
        draw_text(&mut two, 0, 0, "\nH", INK, 1);
        draw_text(&mut one, 0, LINE_HEIGHT as i64, "H", INK, 1);
        assert_eq!(one, two);
        assert_eq!(lines_height(2, 1), LINE_HEIGHT + GLYPH_HEIGHT);
        assert_eq!(lines_height(0, 3), 0);
    }

    #[test]
    fn text_is_clipped_at_every_edge_without_panic() {
        for (x, y) in [(-7, -5), (-1000, 3), (15, -1000), (18, 9), (1000, 1000)] {
            let mut img = RgbImage::from_pixel(20, 12, PAPER);
            draw_text(&mut img, x, y, "WM#", INK, 2);
        }
        let mut empty = RgbImage::new(0, 0);
        draw_text(&mut empty, 0, 0, "x", INK, 1);
    }

    #[test]
    fn scale_zero_draws_nothing() {
        let mut img = RgbImage::from_pixel(20, 12, PAPER);
        draw_text(&mut img, 0, 0, "WM", INK, 0);
        assert!(inked(&img).is_empty());
    }

    #[test]
    fn fit_cuts_long_text_with_an_ellipsis() {
        assert_eq!(fit("corrected", 60, 1), "corrected");
        assert_eq!(fit("corrected Euler", 60, 1), "correct...");
        assert!(text_width(&fit("corrected Euler", 60, 1), 1) <= 60);
        assert_eq!(fit("corrected", 12, 1), "");
        assert_eq!(fit("a≥b", 30, 1), "a>=b");
    }
}
