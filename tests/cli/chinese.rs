//! The words drawn by `plot` and `render` in Chinese: chosen by `--lang` or by LANG, with
//! the font embedded in PDFs (rendered back with pdftoppm, text read back with
//! pdftotext), and English with a note where no Chinese font exists.

use std::path::Path;
use std::process::Command;

use crate::{stderr, stewart, stewart_in, tempdir};

/// Run a poppler tool on `pdf`, returning its standard output.
fn poppler(tool: &str, args: &[&str], pdf: &Path, after: &[&str]) -> String {
    let o = Command::new(tool)
        .args(args)
        .arg(pdf)
        .args(after)
        .output()
        .unwrap_or_else(|e| panic!("{tool}: {e}"));
    assert!(
        o.status.success(),
        "{tool}: {}",
        String::from_utf8_lossy(&o.stderr)
    );
    String::from_utf8_lossy(&o.stdout).into_owned()
}

/// The page of `pdf` as RGB pixels at `dpi`.
fn page(pdf: &Path, dpi: u32) -> image::RgbImage {
    let stem = pdf.with_extension("");
    let r = Command::new("pdftoppm")
        .args(["-png", "-r", &dpi.to_string(), "-singlefile"])
        .arg(pdf)
        .arg(&stem)
        .output()
        .unwrap_or_else(|e| panic!("pdftoppm: {e}"));
    assert!(r.status.success(), "{}", String::from_utf8_lossy(&r.stderr));
    image::open(stem.with_extension("png"))
        .map(|i| i.to_rgb8())
        .unwrap_or_else(|e| panic!("{e}"))
}

/// Dark pixels (text and axes) in rows `rows` of `img`.
fn ink(img: &image::RgbImage, rows: std::ops::Range<u32>) -> usize {
    rows.flat_map(|y| (0..img.width()).map(move |x| (x, y)))
        .filter(|&(x, y)| img.get_pixel(x, y).0.iter().all(|&c| c < 110))
        .count()
}

#[test]
fn a_chinese_plot_opens_anywhere_with_its_characters() {
    let dir = tempdir();
    let zh = dir.path().join("zh.pdf");
    let en = dir.path().join("en.pdf");
    for (lang, path) in [("zh", &zh), ("en", &en)] {
        let out = path.display().to_string();
        let o = stewart(&["plot", "--preset", "paired", "--lang", lang, "--out", &out]);
        assert!(o.status.success(), "{}", stderr(&o));
    }
    // The Chinese font travels inside the file.
    let fonts = poppler("pdffonts", &[], &zh, &[]);
    let cjk = fonts
        .lines()
        .find(|l| l.contains("WenQuanYi") || l.contains("Noto") || l.contains("CJK"))
        .unwrap_or_else(|| panic!("no Chinese font in the PDF:\n{fonts}"));
    assert!(
        cjk.contains(" yes "),
        "the Chinese font is not embedded: {cjk}"
    );
    // The characters read back (a missing glyph would not map to them).
    let text = poppler("pdftotext", &["-q"], &zh, &["-"]);
    let text = text.replace(char::is_whitespace, "");
    assert!(text.contains("腿长—paired"), "{text}");
    assert!(
        text.contains("时间t(s)") && text.contains("腿长L(m)"),
        "{text}"
    );
    assert!(text.contains("L上限") && text.contains("L下限"), "{text}");
    // And the page shows them: the title row has ink, and other ink than the English one.
    let (zh_page, en_page) = (page(&zh, 100), page(&en, 100));
    assert_eq!(zh_page.dimensions(), en_page.dimensions());
    let title = 0..(zh_page.height() / 12);
    assert!(ink(&zh_page, title.clone()) > 100, "no title drawn");
    let differing = title
        .flat_map(|y| (0..zh_page.width()).map(move |x| (x, y)))
        .filter(|&(x, y)| zh_page.get_pixel(x, y) != en_page.get_pixel(x, y))
        .count();
    assert!(
        differing > 100,
        "the Chinese title looks like the English one"
    );
}

#[test]
fn the_environment_chooses_chinese_and_lang_overrides_it() {
    let dir = tempdir();
    let svg = dir.path().join("p.svg");
    let out = svg.display().to_string();
    let zh_env = [("LANG", "zh_CN.UTF-8")];
    let o = stewart_in(&zh_env, &["plot", "--out", &out], b"");
    assert!(o.status.success(), "{}", stderr(&o));
    let text = std::fs::read_to_string(&svg).unwrap_or_default();
    assert!(
        text.contains("腿长 — seed") && text.contains("时间 t (s)"),
        "{text}"
    );
    assert!(
        text.contains("WenQuanYi Micro Hei"),
        "the SVG names a Chinese font"
    );
    let o = stewart_in(&zh_env, &["plot", "--lang", "en", "--out", &out], b"");
    assert!(o.status.success(), "{}", stderr(&o));
    let text = std::fs::read_to_string(&svg).unwrap_or_default();
    assert!(text.contains("Leg lengths — seed") && !text.contains("腿长"));
    // LC_ALL outranks LANG, as in the C library.
    let o = stewart_in(
        &[("LANG", "en_GB.UTF-8"), ("LC_ALL", "zh_CN.UTF-8")],
        &["plot", "--out", &out],
        b"",
    );
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(
        std::fs::read_to_string(&svg)
            .unwrap_or_default()
            .contains("腿长")
    );
}

#[test]
fn without_a_chinese_font_the_words_fall_back_to_english_with_a_note() {
    let dir = tempdir();
    // A fontconfig that knows only DejaVu: no Chinese font on this "system".
    let conf = dir.path().join("fonts.conf");
    std::fs::write(
        &conf,
        "<?xml version=\"1.0\"?>\n<fontconfig><dir>/usr/share/fonts/truetype/dejavu</dir></fontconfig>\n",
    )
    .unwrap_or_else(|e| panic!("{e}"));
    let svg = dir.path().join("p.svg");
    let out = svg.display().to_string();
    let o = stewart_in(
        &[("FONTCONFIG_FILE", &conf.display().to_string())],
        &["plot", "--lang", "zh", "--out", &out],
        b"",
    );
    assert!(o.status.success(), "{}", stderr(&o));
    let err = stderr(&o);
    assert_eq!(
        err.matches("no font with Chinese characters").count(),
        1,
        "{err}"
    );
    assert!(err.contains("showing English instead"), "{err}");
    let text = std::fs::read_to_string(&svg).unwrap_or_default();
    assert!(text.contains("Leg lengths") && !text.contains("腿长"));
}

#[test]
fn an_unknown_language_is_refused_by_name() {
    let o = stewart(&["plot", "--lang", "fr", "--out", "x.svg"]);
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("`fr` is not a language this program speaks"));
    for command in ["view", "render", "plot", "workspace"] {
        let o = stewart(&[command, "--help"]);
        assert!(
            crate::stdout(&o).contains("--lang <zh|en>"),
            "{command} --help"
        );
    }
}

#[test]
fn a_chinese_composite_frame_carries_the_chinese_readout_and_plot() {
    let dir = tempdir();
    let mut frames = Vec::new();
    for lang in ["zh", "en"] {
        let out = dir.path().join(lang);
        let o = stewart(&[
            "render",
            "--preset",
            "paired",
            "--lang",
            lang,
            "--overlay",
            "--composite",
            "--frames",
            "250..251",
            "--size",
            "960x540",
            "--out",
            &out.display().to_string(),
        ]);
        assert!(o.status.success(), "{}", stderr(&o));
        let first = std::fs::read_dir(&out)
            .ok()
            .and_then(|mut d| d.next())
            .and_then(Result::ok)
            .map(|e| e.path())
            .unwrap_or_else(|| panic!("no frame written"));
        frames.push(
            image::open(first)
                .map(|i| i.to_rgb8())
                .unwrap_or_else(|e| panic!("{e}")),
        );
    }
    let (zh, en) = (&frames[0], &frames[1]);
    let differ = |x0: u32, x1: u32, y0: u32, y1: u32| {
        (y0..y1)
            .flat_map(|y| (x0..x1).map(move |x| (x, y)))
            .filter(|&(x, y)| zh.get_pixel(x, y) != en.get_pixel(x, y))
            .count()
    };
    // The readout (top left of the view) and the plot's words (the right 45 %) change …
    assert!(differ(0, 200, 0, 120) > 50, "the readout is not in Chinese");
    assert!(differ(528, 960, 0, 540) > 200, "the plot is not in Chinese");
    // … the platform in the middle of the view does not.
    assert_eq!(differ(150, 450, 200, 500), 0);
}
