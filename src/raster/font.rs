//! A small built-in bitmap font, so that the pictures can carry their own labels
//! without a font file (the `image` crate draws no text, and the machines that build
//! the pictures need not have any fonts installed).
//!
//! Each glyph is a cell 5 pixels wide and 9 high ([`GLYPH_WIDTH`] × [`GLYPH_HEIGHT`]),
//! one `u8` per row from the top, bit 4 the leftmost column and bit 0 the rightmost:
//! 7 rows down to the baseline (capitals and digits fill them) and 2 rows for the
//! descenders of `g j p q y , ;` (and the full height of `| ( )`). The shapes follow
//! the classic 5×7 character-LCD font. The table covers the digits, the
//! ASCII letters, space and `- . , : ; | ( ) / + = % ' _ < > ^ ! ? * #`, and a few
//! non-ASCII signs the labels use (`−` and `–` draw as `-`, `·`, `°`, `×`, `…`, `≥`,
//! `≤`). Any other character draws as the outline of the glyph box ([`UNKNOWN`]), so
//! that a missing glyph is visible rather than silently dropped.
//!
//! Text is drawn with [`draw_text`] at an integer scale (each font pixel a
//! `scale × scale` square); characters advance by [`ADVANCE`] font pixels (one blank
//! column between glyphs) and lines by [`LINE_HEIGHT`].

use image::{Rgb, RgbImage};

/// Width of a glyph in font pixels.
pub const GLYPH_WIDTH: u32 = 5;
/// Height of a glyph cell in font pixels, descenders included.
pub const GLYPH_HEIGHT: u32 = 9;
/// Horizontal advance from one character to the next, in font pixels.
pub const ADVANCE: u32 = 6;
/// Vertical advance from one line to the next, in font pixels.
pub const LINE_HEIGHT: u32 = 11;

/// The glyph drawn for characters the table lacks: the outline of the 5×7 box above
/// the baseline.
pub const UNKNOWN: [u8; 9] = [0x1F, 0x11, 0x11, 0x11, 0x11, 0x11, 0x1F, 0x00, 0x00];

/// The glyph of `c`, rows from the top (bit 4 leftmost); `None` if the table lacks it.
pub fn glyph(c: char) -> Option<[u8; 9]> {
    Some(match c {
        ' ' => [0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00],
        '0' => [0x0E, 0x11, 0x13, 0x15, 0x19, 0x11, 0x0E, 0x00, 0x00],
        '1' => [0x04, 0x0C, 0x04, 0x04, 0x04, 0x04, 0x0E, 0x00, 0x00],
        '2' => [0x0E, 0x11, 0x01, 0x02, 0x04, 0x08, 0x1F, 0x00, 0x00],
        '3' => [0x1F, 0x02, 0x04, 0x02, 0x01, 0x11, 0x0E, 0x00, 0x00],
        '4' => [0x02, 0x06, 0x0A, 0x12, 0x1F, 0x02, 0x02, 0x00, 0x00],
        '5' => [0x1F, 0x10, 0x1E, 0x01, 0x01, 0x11, 0x0E, 0x00, 0x00],
        '6' => [0x06, 0x08, 0x10, 0x1E, 0x11, 0x11, 0x0E, 0x00, 0x00],
        '7' => [0x1F, 0x01, 0x02, 0x04, 0x08, 0x08, 0x08, 0x00, 0x00],
        '8' => [0x0E, 0x11, 0x11, 0x0E, 0x11, 0x11, 0x0E, 0x00, 0x00],
        '9' => [0x0E, 0x11, 0x11, 0x0F, 0x01, 0x02, 0x0C, 0x00, 0x00],
        'A' => [0x0E, 0x11, 0x11, 0x11, 0x1F, 0x11, 0x11, 0x00, 0x00],
        'B' => [0x1E, 0x11, 0x11, 0x1E, 0x11, 0x11, 0x1E, 0x00, 0x00],
        'C' => [0x0E, 0x11, 0x10, 0x10, 0x10, 0x11, 0x0E, 0x00, 0x00],
        'D' => [0x1C, 0x12, 0x11, 0x11, 0x11, 0x12, 0x1C, 0x00, 0x00],
        'E' => [0x1F, 0x10, 0x10, 0x1E, 0x10, 0x10, 0x1F, 0x00, 0x00],
        'F' => [0x1F, 0x10, 0x10, 0x1E, 0x10, 0x10, 0x10, 0x00, 0x00],
        'G' => [0x0E, 0x11, 0x10, 0x17, 0x11, 0x11, 0x0F, 0x00, 0x00],
        'H' => [0x11, 0x11, 0x11, 0x1F, 0x11, 0x11, 0x11, 0x00, 0x00],
        'I' => [0x0E, 0x04, 0x04, 0x04, 0x04, 0x04, 0x0E, 0x00, 0x00],
        'J' => [0x07, 0x02, 0x02, 0x02, 0x02, 0x12, 0x0C, 0x00, 0x00],
        'K' => [0x11, 0x12, 0x14, 0x18, 0x14, 0x12, 0x11, 0x00, 0x00],
        'L' => [0x10, 0x10, 0x10, 0x10, 0x10, 0x10, 0x1F, 0x00, 0x00],
        'M' => [0x11, 0x1B, 0x15, 0x15, 0x11, 0x11, 0x11, 0x00, 0x00],
        'N' => [0x11, 0x11, 0x19, 0x15, 0x13, 0x11, 0x11, 0x00, 0x00],
        'O' => [0x0E, 0x11, 0x11, 0x11, 0x11, 0x11, 0x0E, 0x00, 0x00],
        'P' => [0x1E, 0x11, 0x11, 0x1E, 0x10, 0x10, 0x10, 0x00, 0x00],
        'Q' => [0x0E, 0x11, 0x11, 0x11, 0x15, 0x12, 0x0D, 0x00, 0x00],
        'R' => [0x1E, 0x11, 0x11, 0x1E, 0x14, 0x12, 0x11, 0x00, 0x00],
        'S' => [0x0F, 0x10, 0x10, 0x0E, 0x01, 0x01, 0x1E, 0x00, 0x00],
        'T' => [0x1F, 0x04, 0x04, 0x04, 0x04, 0x04, 0x04, 0x00, 0x00],
        'U' => [0x11, 0x11, 0x11, 0x11, 0x11, 0x11, 0x0E, 0x00, 0x00],
        'V' => [0x11, 0x11, 0x11, 0x11, 0x11, 0x0A, 0x04, 0x00, 0x00],
        'W' => [0x11, 0x11, 0x11, 0x15, 0x15, 0x15, 0x0A, 0x00, 0x00],
        'X' => [0x11, 0x11, 0x0A, 0x04, 0x0A, 0x11, 0x11, 0x00, 0x00],
        'Y' => [0x11, 0x11, 0x11, 0x0A, 0x04, 0x04, 0x04, 0x00, 0x00],
        'Z' => [0x1F, 0x01, 0x02, 0x04, 0x08, 0x10, 0x1F, 0x00, 0x00],
        'a' => [0x00, 0x00, 0x0E, 0x01, 0x0F, 0x11, 0x0F, 0x00, 0x00],
        'b' => [0x10, 0x10, 0x16, 0x19, 0x11, 0x11, 0x1E, 0x00, 0x00],
        'c' => [0x00, 0x00, 0x0E, 0x10, 0x10, 0x11, 0x0E, 0x00, 0x00],
        'd' => [0x01, 0x01, 0x0D, 0x13, 0x11, 0x11, 0x0F, 0x00, 0x00],
        'e' => [0x00, 0x00, 0x0E, 0x11, 0x1F, 0x10, 0x0E, 0x00, 0x00],
        'f' => [0x06, 0x09, 0x08, 0x1C, 0x08, 0x08, 0x08, 0x00, 0x00],
        'g' => [0x00, 0x00, 0x0F, 0x11, 0x11, 0x11, 0x0F, 0x01, 0x0E],
        'h' => [0x10, 0x10, 0x16, 0x19, 0x11, 0x11, 0x11, 0x00, 0x00],
        'i' => [0x04, 0x00, 0x0C, 0x04, 0x04, 0x04, 0x0E, 0x00, 0x00],
        'j' => [0x02, 0x00, 0x06, 0x02, 0x02, 0x02, 0x02, 0x12, 0x0C],
        'k' => [0x10, 0x10, 0x12, 0x14, 0x18, 0x14, 0x12, 0x00, 0x00],
        'l' => [0x0C, 0x04, 0x04, 0x04, 0x04, 0x04, 0x0E, 0x00, 0x00],
        'm' => [0x00, 0x00, 0x1A, 0x15, 0x15, 0x11, 0x11, 0x00, 0x00],
        'n' => [0x00, 0x00, 0x16, 0x19, 0x11, 0x11, 0x11, 0x00, 0x00],
        'o' => [0x00, 0x00, 0x0E, 0x11, 0x11, 0x11, 0x0E, 0x00, 0x00],
        'p' => [0x00, 0x00, 0x1E, 0x11, 0x11, 0x11, 0x1E, 0x10, 0x10],
        'q' => [0x00, 0x00, 0x0F, 0x11, 0x11, 0x11, 0x0F, 0x01, 0x01],
        'r' => [0x00, 0x00, 0x16, 0x19, 0x10, 0x10, 0x10, 0x00, 0x00],
        's' => [0x00, 0x00, 0x0E, 0x10, 0x0E, 0x01, 0x1E, 0x00, 0x00],
        't' => [0x08, 0x08, 0x1C, 0x08, 0x08, 0x09, 0x06, 0x00, 0x00],
        'u' => [0x00, 0x00, 0x11, 0x11, 0x11, 0x13, 0x0D, 0x00, 0x00],
        'v' => [0x00, 0x00, 0x11, 0x11, 0x11, 0x0A, 0x04, 0x00, 0x00],
        'w' => [0x00, 0x00, 0x11, 0x11, 0x15, 0x15, 0x0A, 0x00, 0x00],
        'x' => [0x00, 0x00, 0x11, 0x0A, 0x04, 0x0A, 0x11, 0x00, 0x00],
        'y' => [0x00, 0x00, 0x11, 0x11, 0x11, 0x11, 0x0F, 0x01, 0x0E],
        'z' => [0x00, 0x00, 0x1F, 0x02, 0x04, 0x08, 0x1F, 0x00, 0x00],
        '-' | '−' | '–' => [0x00, 0x00, 0x00, 0x1F, 0x00, 0x00, 0x00, 0x00, 0x00],
        '.' => [0x00, 0x00, 0x00, 0x00, 0x00, 0x0C, 0x0C, 0x00, 0x00],
        ',' => [0x00, 0x00, 0x00, 0x00, 0x00, 0x0C, 0x0C, 0x04, 0x08],
        ':' => [0x00, 0x0C, 0x0C, 0x00, 0x0C, 0x0C, 0x00, 0x00, 0x00],
        ';' => [0x00, 0x00, 0x0C, 0x0C, 0x00, 0x0C, 0x0C, 0x04, 0x08],
        '|' => [0x04, 0x04, 0x04, 0x04, 0x04, 0x04, 0x04, 0x04, 0x04],
        '(' => [0x02, 0x04, 0x08, 0x08, 0x08, 0x08, 0x08, 0x04, 0x02],
        ')' => [0x08, 0x04, 0x02, 0x02, 0x02, 0x02, 0x02, 0x04, 0x08],
        '/' => [0x00, 0x01, 0x02, 0x04, 0x08, 0x10, 0x00, 0x00, 0x00],
        '+' => [0x00, 0x04, 0x04, 0x1F, 0x04, 0x04, 0x00, 0x00, 0x00],
        '=' => [0x00, 0x00, 0x1F, 0x00, 0x1F, 0x00, 0x00, 0x00, 0x00],
        '%' => [0x18, 0x19, 0x02, 0x04, 0x08, 0x13, 0x03, 0x00, 0x00],
        '\'' => [0x0C, 0x04, 0x08, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00],
        '_' => [0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x1F, 0x00, 0x00],
        '<' => [0x02, 0x04, 0x08, 0x10, 0x08, 0x04, 0x02, 0x00, 0x00],
        '>' => [0x08, 0x04, 0x02, 0x01, 0x02, 0x04, 0x08, 0x00, 0x00],
        '^' => [0x04, 0x0A, 0x11, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00],
        '!' => [0x04, 0x04, 0x04, 0x04, 0x00, 0x00, 0x04, 0x00, 0x00],
        '?' => [0x0E, 0x11, 0x01, 0x02, 0x04, 0x00, 0x04, 0x00, 0x00],
        '*' => [0x00, 0x04, 0x15, 0x0E, 0x15, 0x04, 0x00, 0x00, 0x00],
        '#' => [0x0A, 0x0A, 0x1F, 0x0A, 0x1F, 0x0A, 0x0A, 0x00, 0x00],
        '·' => [0x00, 0x00, 0x00, 0x04, 0x00, 0x00, 0x00, 0x00, 0x00],
        '°' => [0x0C, 0x12, 0x12, 0x0C, 0x00, 0x00, 0x00, 0x00, 0x00],
        '×' => [0x00, 0x11, 0x0A, 0x04, 0x0A, 0x11, 0x00, 0x00, 0x00],
        '…' => [0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x15, 0x00, 0x00],
        '≥' => [0x08, 0x04, 0x02, 0x04, 0x08, 0x00, 0x1F, 0x00, 0x00],
        '≤' => [0x02, 0x04, 0x08, 0x04, 0x02, 0x00, 0x1F, 0x00, 0x00],
        _ => return None,
    })
}

/// The width in image pixels of `text` drawn on one line at `scale`: [`ADVANCE`] per
/// character, without the blank column after the last one (0 for empty text).
pub fn text_width(text: &str, scale: u32) -> u32 {
    let n = text.chars().count() as u32;
    if n == 0 {
        0
    } else {
        (n * ADVANCE - (ADVANCE - GLYPH_WIDTH)) * scale
    }
}

/// `text` cut to fit `width` pixels at `scale`: whole if it fits, else as many of its
/// first characters as fit followed by `…` (just `…`, or nothing, when even that is too
/// wide).
pub fn fit(text: &str, width: u32, scale: u32) -> String {
    if text_width(text, scale) <= width {
        return text.to_string();
    }
    let mut out = String::new();
    for c in text.chars() {
        out.push(c);
        if text_width(&format!("{out}…"), scale) > width {
            out.pop();
            break;
        }
    }
    out.push('…');
    if text_width(&out, scale) <= width {
        out
    } else {
        String::new()
    }
}

/// The height in image pixels of one line of text at `scale` (the glyph cell with its
/// descenders, without the gap to the next line).
pub fn text_height(scale: u32) -> u32 {
    GLYPH_HEIGHT * scale
}

/// Draws `text` on one line with the top-left corner of its first glyph at `(x, y)`,
/// each font pixel a `scale × scale` square of `colour` (a scale of 0 draws nothing).
/// Only the glyphs' set pixels are drawn, so the background shows between them.
/// Whatever falls outside the image is clipped: `x` and `y` may be negative or past the
/// edges. Characters the table lacks draw as [`UNKNOWN`].
pub fn draw_text(img: &mut RgbImage, x: i64, y: i64, text: &str, colour: Rgb<u8>, scale: u32) {
    let (w, h) = (i64::from(img.width()), i64::from(img.height()));
    let s = i64::from(scale);
    for (k, c) in text.chars().enumerate() {
        let gx = x + k as i64 * i64::from(ADVANCE) * s;
        if gx >= w {
            break;
        }
        let rows = glyph(c).unwrap_or(UNKNOWN);
        for (r, bits) in rows.iter().enumerate() {
            for col in 0..GLYPH_WIDTH {
                if bits & (0x10 >> col) == 0 {
                    continue;
                }
                let (px, py) = (gx + i64::from(col) * s, y + r as i64 * s);
                for dy in 0..s {
                    for dx in 0..s {
                        let (qx, qy) = (px + dx, py + dy);
                        if (0..w).contains(&qx) && (0..h).contains(&qy) {
                            img.put_pixel(qx as u32, qy as u32, colour);
                        }
                    }
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const INK: Rgb<u8> = Rgb([255, 255, 255]);
    const PAPER: Rgb<u8> = Rgb([0, 0, 0]);

    /// The set pixels of `img` as strings of `#` and `.`, one per row.
    fn rows(img: &RgbImage) -> Vec<String> {
        (0..img.height())
            .map(|y| {
                (0..img.width())
                    .map(|x| {
                        if *img.get_pixel(x, y) == INK {
                            '#'
                        } else {
                            '.'
                        }
                    })
                    .collect()
            })
            .collect()
    }

    #[test]
    fn a_glyph_draws_exactly_the_pixels_of_its_bitmap() {
        let mut img = RgbImage::from_pixel(7, 11, PAPER);
        draw_text(&mut img, 1, 1, "1", INK, 1);
        assert_eq!(
            rows(&img),
            [
                ".......", "...#...", "..##...", "...#...", "...#...", "...#...", "...#...",
                "..###..", ".......", ".......", ".......",
            ]
        );
        let mut img = RgbImage::from_pixel(5, 9, PAPER);
        draw_text(&mut img, 0, 0, "g", INK, 1);
        assert_eq!(
            rows(&img),
            [".....", ".....", ".####", "#...#", "#...#", "#...#", ".####", "....#", ".###."]
        );
    }

    #[test]
    fn every_glyph_matches_its_table_entry_at_scale_two() {
        for c in "0123456789ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz-.|()/: ".chars() {
            let g = glyph(c).expect("in the table");
            let mut img = RgbImage::from_pixel(10, 18, PAPER);
            draw_text(&mut img, 0, 0, &c.to_string(), INK, 2);
            for y in 0..18 {
                for x in 0..10 {
                    let set = g[(y / 2) as usize] & (0x10 >> (x / 2)) != 0;
                    assert_eq!(*img.get_pixel(x, y) == INK, set, "{c:?} at ({x}, {y})");
                }
            }
        }
    }

    #[test]
    fn glyphs_fit_in_five_columns_and_differ() {
        let chars: Vec<char> = "0123456789ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz"
            .chars()
            .collect();
        for c in &chars {
            let g = glyph(*c).expect("in the table");
            assert!(g.iter().all(|r| r & !0x1F == 0), "{c:?} is wider than 5");
            assert!(g.iter().any(|r| *r != 0), "{c:?} is blank");
        }
        for (i, a) in chars.iter().enumerate() {
            for b in &chars[i + 1..] {
                assert_ne!(glyph(*a), glyph(*b), "{a:?} and {b:?} look alike");
            }
        }
    }

    #[test]
    fn the_minus_signs_draw_as_the_hyphen() {
        assert_eq!(glyph('−'), glyph('-'));
        assert_eq!(glyph('–'), glyph('-'));
    }

    #[test]
    fn an_unknown_character_draws_the_box_outline() {
        assert_eq!(glyph('€'), None);
        let mut img = RgbImage::from_pixel(5, 9, PAPER);
        draw_text(&mut img, 0, 0, "€", INK, 1);
        assert_eq!(
            rows(&img),
            ["#####", "#...#", "#...#", "#...#", "#...#", "#...#", "#####", ".....", "....."]
        );
    }

    #[test]
    fn characters_advance_by_six_and_widths_agree() {
        let mut img = RgbImage::from_pixel(20, 7, PAPER);
        draw_text(&mut img, 0, 0, "||", INK, 1);
        let set: Vec<u32> = (0..20).filter(|&x| *img.get_pixel(x, 3) == INK).collect();
        assert_eq!(set, [2, 8]);
        assert_eq!(text_width("", 3), 0);
        assert_eq!(text_width("|", 1), 5);
        assert_eq!(text_width("||", 1), 11);
        assert_eq!(text_width("abc", 2), 34);
        assert_eq!(text_height(3), 27);
    }

    #[test]
    fn text_is_clipped_at_every_edge_without_panic() {
        let mut img = RgbImage::from_pixel(8, 8, PAPER);
        for (x, y) in [
            (-3, -3),
            (5, 5),
            (-100, 2),
            (2, -100),
            (7, 7),
            (i64::MIN / 4, 0),
        ] {
            draw_text(&mut img, x, y, "W8|€", INK, 3);
        }
        draw_text(&mut img, 1_000_000, 1_000_000, "far away", INK, 2);
        // What is drawn past the top-left corner is the same text, cut: text at
        // (-3, -4) shows what text at (10, 10) shows 13 and 14 pixels further on.
        let mut whole = RgbImage::from_pixel(60, 40, PAPER);
        draw_text(&mut whole, 10, 10, "W8", INK, 2);
        let mut cut = RgbImage::from_pixel(20, 12, PAPER);
        draw_text(&mut cut, -3, -4, "W8", INK, 2);
        for y in 0..12 {
            for x in 0..20 {
                assert_eq!(
                    cut.get_pixel(x, y),
                    whole.get_pixel(x + 13, y + 14),
                    "({x}, {y})"
                );
            }
        }
        assert!(cut.pixels().any(|p| *p == INK));
    }

    #[test]
    fn fit_cuts_long_text_with_an_ellipsis() {
        assert_eq!(fit("angular", 100, 1), "angular");
        // 6 pixels a character, 5 for the last: "angu…" is 29 wide.
        assert_eq!(fit("angular-span-table", 29, 1), "angu…");
        assert_eq!(fit("angular-span-table", 34, 1), "angu…");
        assert_eq!(fit("angular-span-table", 35, 1), "angul…");
        assert_eq!(fit("angular", 5, 1), "…");
        assert_eq!(fit("angular", 4, 1), "");
        assert!(text_width(&fit("angular-span-table", 96, 1), 1) <= 96);
    }

    #[test]
    fn scale_zero_draws_nothing() {
        let mut img = RgbImage::from_pixel(8, 8, PAPER);
        draw_text(&mut img, 0, 0, "8", INK, 0);
        assert!(img.pixels().all(|p| *p == PAPER));
    }
}
