//! GIF frames that carry only what changed since the previous frame: the smallest
//! rectangle holding every changed pixel, with the unchanged pixels inside it
//! transparent, drawn over the previous frame (disposal "keep").
//!
//! A platform moving over a still background changes a small part of each frame, so
//! this keeps a GIF several times smaller than full frames and quantises fewer pixels.
//! Each frame gets its own palette: up to 255 colours (the 256th is the transparent
//! one), exact when the changed part has that few colours; otherwise its frequent
//! (flat) colours exactly and NeuQuant for the rest.

use std::borrow::Cow;
use std::collections::HashMap;

use stewart_render::Image;

/// NeuQuant's sampling: 10 is the gif crate's own default, a good balance of speed and
/// colour (1 is slowest and best, 30 fastest).
const NEUQUANT_SPEED: i32 = 10;

/// Colours a frame's palette gives the picture; the last index is transparency.
const OPAQUE_COLOURS: usize = 255;

/// The transparent index.
const TRANSPARENT: u8 = 255;

/// Most palette entries given to a frame's flat colours exactly (the rest go to
/// NeuQuant).
const FLAT_MAX_COLOURS: usize = 128;

/// Flat colours are counted on every this many pixels of the frame (a prime, so that
/// the sampling does not follow the rows).
const FLAT_STRIDE: usize = 7;

/// A flat colour is seen at least this many times (and in one sample in a thousand).
const FLAT_MIN_SAMPLES: u32 = 16;

/// A rectangle of pixels.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct Rect {
    /// Left column.
    pub(crate) left: u32,
    /// Top row.
    pub(crate) top: u32,
    /// Width, pixels.
    pub(crate) width: u32,
    /// Height, pixels.
    pub(crate) height: u32,
}

/// The smallest rectangle holding every pixel in which `current` differs from
/// `previous` (same size), or `None` when they are identical.
pub(crate) fn changed_rect(previous: &Image, current: &Image) -> Option<Rect> {
    let w = current.width as usize;
    let row_bytes = 4 * w;
    let rows = || {
        previous
            .rgba
            .chunks_exact(row_bytes)
            .zip(current.rgba.chunks_exact(row_bytes))
    };
    let top = rows().position(|(a, b)| a != b)?;
    let bottom = rows().rposition(|(a, b)| a != b)?;
    let (mut left, mut right) = (w, 0);
    for (a, b) in rows().skip(top).take(bottom + 1 - top) {
        if a == b {
            continue;
        }
        let differs = |x: &usize| a[4 * x..4 * x + 4] != b[4 * x..4 * x + 4];
        if let Some(l) = (0..left).find(differs) {
            left = l;
        }
        if let Some(r) = (right..w).rev().find(differs) {
            right = r;
        }
    }
    Some(Rect {
        left: left as u32,
        top: top as u32,
        width: (right + 1 - left) as u32,
        height: (bottom + 1 - top) as u32,
    })
}

/// The GIF frame that turns `previous` (as shown) into `current`; the whole frame when
/// there is no previous one. The delay is left for the caller.
pub(crate) fn delta_frame(previous: Option<&Image>, current: &Image) -> gif::Frame<'static> {
    let full = Rect {
        left: 0,
        top: 0,
        width: current.width,
        height: current.height,
    };
    let rect = match previous {
        None => full,
        Some(p) => match changed_rect(p, current) {
            Some(r) => r,
            // Nothing changed: one transparent pixel keeps the frame (and its delay).
            None => {
                return gif::Frame {
                    width: 1,
                    height: 1,
                    buffer: Cow::Owned(vec![0]),
                    palette: Some(vec![0, 0, 0]),
                    transparent: Some(0),
                    dispose: gif::DisposalMethod::Keep,
                    ..gif::Frame::default()
                };
            }
        },
    };
    // `None` marks a pixel that the previous frame already shows.
    let stride = current.width as usize;
    let mut pixels: Vec<Option<[u8; 4]>> =
        Vec::with_capacity(rect.width as usize * rect.height as usize);
    for y in rect.top as usize..(rect.top + rect.height) as usize {
        for x in rect.left as usize..(rect.left + rect.width) as usize {
            let i = 4 * (y * stride + x);
            let c = [
                current.rgba[i],
                current.rgba[i + 1],
                current.rgba[i + 2],
                255,
            ];
            let same = previous.is_some_and(|p| p.rgba[i..i + 3] == c[..3]);
            pixels.push((!same).then_some(c));
        }
    }
    let (palette, buffer) = quantise(&pixels, &flat_colours(current));
    gif::Frame {
        width: rect.width as u16,
        height: rect.height as u16,
        left: rect.left as u16,
        top: rect.top as u16,
        buffer: Cow::Owned(buffer),
        palette: Some(palette),
        transparent: pixels.iter().any(Option::is_none).then_some(TRANSPARENT),
        dispose: gif::DisposalMethod::Keep,
        ..gif::Frame::default()
    }
}

/// The colours of the frame's flat areas (background, plates, grid), most frequent
/// first: those covering at least one pixel in a thousand of the whole frame, counted
/// on every 7th pixel. Counted on the whole frame, not the changed part, so that a flat
/// colour is one in every frame however little of it changes.
fn flat_colours(frame: &Image) -> Vec<[u8; 4]> {
    let mut counts: HashMap<[u8; 4], u32> = HashMap::new();
    let mut samples = 0u32;
    for p in frame.rgba.chunks_exact(4).step_by(FLAT_STRIDE) {
        *counts.entry([p[0], p[1], p[2], 255]).or_default() += 1;
        samples += 1;
    }
    let floor = (samples / 1000).max(FLAT_MIN_SAMPLES);
    let mut flat: Vec<([u8; 4], u32)> = counts.into_iter().filter(|(_, n)| *n >= floor).collect();
    // Most frequent first; ties by colour, so the choice never depends on hashing.
    flat.sort_unstable_by(|a, b| b.1.cmp(&a.1).then(a.0.cmp(&b.0)));
    flat.into_iter()
        .take(FLAT_MAX_COLOURS)
        .map(|(c, _)| c)
        .collect()
}

/// A palette (RGB triples) of at most 255 colours for the opaque pixels, and each
/// pixel's index (`TRANSPARENT` for `None`).
///
/// When the changed part has more colours than that, the frame's `flat` colours get
/// exact entries, so that a flat area redrawn in a later frame matches the part of it
/// that earlier frames left in place (per-frame NeuQuant palettes would differ by a few
/// levels and show as streaks), and NeuQuant shares the remaining entries among the
/// other colours (shading, edges).
fn quantise(pixels: &[Option<[u8; 4]>], flat: &[[u8; 4]]) -> (Vec<u8>, Vec<u8>) {
    let mut distinct: Vec<[u8; 4]> = pixels.iter().flatten().copied().collect();
    distinct.sort_unstable();
    distinct.dedup();
    let exact: Vec<[u8; 4]> = if distinct.len() <= OPAQUE_COLOURS {
        distinct
    } else {
        flat.iter()
            .filter(|c| distinct.binary_search(c).is_ok())
            .copied()
            .collect()
    };
    let reserved = exact.len();
    let index: HashMap<[u8; 4], u8> = exact
        .iter()
        .enumerate()
        .map(|(i, c)| (*c, i as u8))
        .collect();
    let mut palette = Vec::with_capacity(3 * 256);
    palette.extend(exact.iter().flat_map(|c| [c[0], c[1], c[2]]));
    let rest: Vec<u8> = pixels
        .iter()
        .flatten()
        .filter(|c| !index.contains_key(*c))
        .flatten()
        .copied()
        .collect();
    let nq = (!rest.is_empty()).then(|| {
        // At least about 50 000 samples, so that small changed parts are learnt well.
        let sampling = (rest.len() / 4 / 50_000).clamp(1, NEUQUANT_SPEED as usize) as i32;
        let nq = color_quant::NeuQuant::new(sampling, OPAQUE_COLOURS - reserved, &rest);
        palette.extend(nq.color_map_rgb());
        nq
    });
    let buffer = pixels
        .iter()
        .map(|p| match (p, &nq) {
            (None, _) => TRANSPARENT,
            (Some(c), nq) => match (index.get(c), nq) {
                (Some(i), _) => *i,
                (None, Some(nq)) => (reserved + nq.index_of(c)) as u8,
                (None, None) => 0,
            },
        })
        .collect();
    // Pad to 256 entries so that the transparent index exists in the table.
    palette.resize(3 * 256, 0);
    (palette, buffer)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn frame(width: u32, height: u32, paint: impl Fn(u32, u32) -> [u8; 4]) -> Image {
        let mut rgba = Vec::new();
        for y in 0..height {
            for x in 0..width {
                rgba.extend(paint(x, y));
            }
        }
        Image {
            width,
            height,
            rgba,
        }
    }

    /// A smooth gradient (thousands of colours, so NeuQuant is used) with a square at `at`.
    fn scene(at: u32) -> Image {
        frame(96, 64, |x, y| {
            if (at..at + 12).contains(&x) && (20..32).contains(&y) {
                [230, 40, 40, 255]
            } else {
                [(x * 2) as u8, (y * 3) as u8, 90, 255]
            }
        })
    }

    #[test]
    fn the_changed_rectangle_is_tight() {
        let a = scene(10);
        let b = scene(14);
        assert_eq!(
            changed_rect(&a, &b),
            Some(Rect {
                left: 10,
                top: 20,
                width: 16,
                height: 12
            })
        );
        assert_eq!(changed_rect(&a, &a), None);
        let mut c = a.clone();
        c.rgba[4 * (63 * 96 + 95)] ^= 1;
        assert_eq!(
            changed_rect(&a, &c),
            Some(Rect {
                left: 95,
                top: 63,
                width: 1,
                height: 1
            })
        );
    }

    /// Encode `frames` as delta frames and compose them as a viewer does: the picture
    /// shown after each frame, and each frame's delay and area.
    fn shown(frames: &[Image]) -> (Vec<Vec<u8>>, Vec<(u16, u32)>) {
        let (w, h) = (frames[0].width, frames[0].height);
        let mut bytes = Vec::new();
        {
            let mut encoder = gif::Encoder::new(&mut bytes, w as u16, h as u16, &[])
                .unwrap_or_else(|e| panic!("{e}"));
            let mut previous: Option<&Image> = None;
            for f in frames {
                let mut g = delta_frame(previous, f);
                g.delay = 4;
                encoder.write_frame(&g).unwrap_or_else(|e| panic!("{e}"));
                previous = Some(f);
            }
        }
        let mut options = gif::DecodeOptions::new();
        options.set_color_output(gif::ColorOutput::RGBA);
        let mut decoder = options
            .read_info(bytes.as_slice())
            .unwrap_or_else(|e| panic!("{e}"));
        let mut canvas = vec![0u8; (w * h * 4) as usize];
        let (mut pictures, mut written) = (Vec::new(), Vec::new());
        while let Some(f) = decoder.read_next_frame().unwrap_or_else(|e| panic!("{e}")) {
            written.push((f.delay, u32::from(f.width) * u32::from(f.height)));
            for y in 0..u32::from(f.height) {
                for x in 0..u32::from(f.width) {
                    let s = 4 * (y * u32::from(f.width) + x) as usize;
                    if f.buffer[s + 3] == 0 {
                        continue;
                    }
                    let (cx, cy) = (x + u32::from(f.left), y + u32::from(f.top));
                    let d = 4 * (cy * w + cx) as usize;
                    canvas[d..d + 4].copy_from_slice(&f.buffer[s..s + 4]);
                }
            }
            pictures.push(canvas.clone());
        }
        (pictures, written)
    }

    #[test]
    fn delta_frames_decode_to_the_original_pictures() {
        let frames: Vec<Image> = [10, 14, 14, 30, 60].into_iter().map(scene).collect();
        let (pictures, written) = shown(&frames);
        assert_eq!(pictures.len(), frames.len());
        // The first frame, quantised by NeuQuant: close on average.
        let errors: Vec<u8> = pictures[0]
            .iter()
            .zip(&frames[0].rgba)
            .map(|(a, b)| a.abs_diff(*b))
            .collect();
        let mean = errors.iter().map(|e| f64::from(*e)).sum::<f64>() / errors.len() as f64;
        assert!(mean < 3.0, "mean colour error {mean}");
        // Later frames: what changed is exact (few colours, an exact palette); everything
        // else still shows the first frame as it was shown.
        for (picture, original) in pictures.iter().zip(&frames).skip(1) {
            for i in (0..picture.len()).step_by(4) {
                let exact = picture[i..i + 3] == original.rgba[i..i + 3];
                let kept = original.rgba[i..i + 4] == frames[0].rgba[i..i + 4]
                    && picture[i..i + 4] == pictures[0][i..i + 4];
                assert!(exact || kept, "pixel {} differs", i / 4);
            }
        }
        // First frame whole; then only the square's old and new places; an unchanged
        // frame is one pixel. Every delay is kept.
        let areas: Vec<u32> = written.iter().map(|w| w.1).collect();
        assert_eq!(areas, [96 * 64, 16 * 12, 1, 28 * 12, 42 * 12]);
        assert!(written.iter().all(|w| w.0 == 4));
    }

    #[test]
    fn a_flat_area_redrawn_later_matches_what_stayed() {
        // A flat grey plate on a background of thousands of colours, and a shaded bar
        // sweeping over the plate: wherever the plate shows, in every frame, it has its
        // exact colour, so the parts the bar uncovers match the parts that stayed.
        let plate = [120, 124, 131, 255];
        let scene = |at: u32| {
            frame(160, 100, move |x, y| {
                if (at..at + 24).contains(&x) && (20..80).contains(&y) {
                    let (r, g, b) = (x * 3 % 21, y % 21, (x + 2 * y) % 21);
                    [(110 + r) as u8, (114 + g) as u8, (121 + b) as u8, 255]
                } else if (20..140).contains(&x) && (45..50).contains(&y) {
                    plate
                } else {
                    [
                        (x * 8 % 256) as u8,
                        (y * 11 % 256) as u8,
                        ((x ^ y) * 3 % 256) as u8,
                        255,
                    ]
                }
            })
        };
        let frames: Vec<Image> = (0..8).map(|k| scene(10 + 15 * k)).collect();
        let (pictures, _) = shown(&frames);
        for (k, (picture, original)) in pictures.iter().zip(&frames).enumerate() {
            for i in (0..picture.len()).step_by(4) {
                if original.rgba[i..i + 4] == plate {
                    assert_eq!(picture[i..i + 3], plate[..3], "frame {k}, pixel {}", i / 4);
                }
            }
        }
    }
}
