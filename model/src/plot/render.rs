//! Draws a [`Figure`] (any of Figs 1-11) with plotters to SVG and PNG, written atomically
//! (temporary file in the target directory, then rename), with its plotted series as CSV.
//!
//! Text: the PNG rasteriser (ab_glyph) uses DejaVu Sans embedded from `model/assets/`, so no
//! system font is needed and the output is the same bytes on every machine. The SVG names the
//! same family (`DejaVu Sans, sans-serif`) and its layout (legend boxes, label areas) was
//! measured with the embedded font's metrics.

use super::axis::{label, Coord};
use super::spec::{Dash, Figure, LegendPlace, Line, Marker, Panel, Rgb, Shape, TextAt};
use super::{PlotError, PlotStyle};
// Titles carry the aircraft's name, whose control characters XML forbids in an SVG even as
// character references (plotters escapes `<`, `&` and quotes, not those): they are drawn
// escaped, as the terminal shows them.
use crate::aircraft::shown;
use plotters::coord::{CoordTranslate, Shift};
use plotters::element::DashedPathElement;
use plotters::prelude::*;
use std::path::{Path, PathBuf};
use std::sync::OnceLock;

/// DejaVu Sans (Bitstream Vera licence, see `model/assets/DejaVuSans-LICENSE.txt`).
static FONT: &[u8] = include_bytes!("../../assets/DejaVuSans.ttf");

/// The family name plotters' text styles use; registered with the embedded font.
const FAMILY: &str = "sans-serif";

/// Registers the embedded font once.
fn register_font() -> Result<(), PlotError> {
    static DONE: OnceLock<bool> = OnceLock::new();
    let ok = *DONE
        .get_or_init(|| plotters::style::register_font(FAMILY, FontStyle::Normal, FONT).is_ok());
    if ok {
        Ok(())
    } else {
        Err(PlotError::Font)
    }
}

/// Font sizes, px (for a 1000 x 700 canvas; scaled with the canvas height).
struct Sizes {
    title: f64,
    caption: f64,
    axis_desc: f64,
    tick: f64,
    legend: f64,
    note: f64,
}

impl Sizes {
    fn for_height(h: u32) -> Sizes {
        let k = (f64::from(h) / 700.0).clamp(0.6, 3.0);
        Sizes {
            title: 24.0 * k,
            caption: 19.0 * k,
            axis_desc: 18.0 * k,
            tick: 15.0 * k,
            legend: 15.0 * k,
            note: 14.0 * k,
        }
    }
}

/// Most ticks asked for on each axis (an upper bound, see [`super::axis::ticks`]); fewer on
/// small panels, so that tick labels never touch.
const X_TICKS: usize = 10;
const Y_TICKS: usize = 8;

/// Tick counts for a panel of `w` x `h` px.
fn tick_counts(w: u32, h: u32, sz: &Sizes) -> (usize, usize) {
    let x = (f64::from(w) / (sz.tick * 5.0)).floor() as usize;
    let y = (f64::from(h) / (sz.tick * 4.0)).floor() as usize;
    (x.clamp(3, X_TICKS), y.clamp(3, Y_TICKS))
}

fn rgb(c: Rgb) -> RGBColor {
    RGBColor(c.0, c.1, c.2)
}

fn draw_err<E: std::error::Error + Send + Sync>(e: DrawingAreaErrorKind<E>) -> PlotError {
    PlotError::Draw(e.to_string())
}

/// `<stem>.<ext>` (the stem may itself contain dots).
pub(crate) fn with_ext(stem: &Path, ext: &str) -> PathBuf {
    let mut s = stem.as_os_str().to_owned();
    s.push(".");
    s.push(ext);
    PathBuf::from(s)
}

fn io_err(path: &Path, e: std::io::Error) -> PlotError {
    PlotError::Io {
        path: path.to_path_buf(),
        message: e.to_string(),
    }
}

/// Renders `fig` to `<stem>.svg` and/or `<stem>.png`, with the plotted series in `<stem>.csv`
/// ([`Figure::to_csv`]); returns the files written. Every file that can be written is; if any
/// cannot, the error is [`PlotError::Files`], naming each failed file and why.
pub(crate) fn render(
    stem: &Path,
    fig: &Figure,
    style: &PlotStyle,
) -> Result<Vec<PathBuf>, PlotError> {
    let (w, h) = (style.width, style.height);
    if !(200..=10_000).contains(&w) || !(150..=10_000).contains(&h) {
        return Err(PlotError::Size {
            width: w,
            height: h,
        });
    }
    register_font()?;
    if let Some(dir) = stem.parent().filter(|d| !d.as_os_str().is_empty()) {
        if !dir.is_dir() {
            return Err(PlotError::Io {
                path: dir.to_path_buf(),
                message: "output directory does not exist".into(),
            });
        }
    }
    let mut written = Vec::new();
    let mut failed = Vec::new();
    // Each failure is listed with its file: an I/O error by the system's message alone.
    let mut outcome = |target: PathBuf, r: Result<(), PlotError>| match r {
        Ok(()) => written.push(target),
        Err(PlotError::Io { message, .. }) => failed.push((target, message)),
        Err(e) => failed.push((target, e.to_string())),
    };
    if style.svg {
        let target = with_ext(stem, "svg");
        let r = (|| {
            let mut svg = String::new();
            {
                let root = SVGBackend::with_string(&mut svg, (w, h)).into_drawing_area();
                draw(&root, fig)?;
                root.present().map_err(draw_err)?;
            }
            let svg = finish_svg(&svg, style.embed_font);
            crate::files::write_atomic(&target, svg.as_bytes()).map_err(|e| io_err(&target, e))
        })();
        outcome(target, r);
    }
    if style.png {
        let target = with_ext(stem, "png");
        // plotters' bitmap backend writes to a path itself: draw to a temporary name, rename.
        crate::files::remove_stale_temporaries(&target);
        let tmp = crate::files::temp_path(&target, ".png");
        let r = (|| {
            // plotters reports a file it cannot create in its own debug format: create it
            // first, for the system's message.
            std::fs::File::create(&tmp).map_err(|e| io_err(&target, e))?;
            let root = BitMapBackend::new(&tmp, (w, h)).into_drawing_area();
            draw(&root, fig)?;
            root.present().map_err(draw_err)?;
            drop(root);
            std::fs::rename(&tmp, &target).map_err(|e| io_err(&target, e))
        })();
        if r.is_err() {
            let _ = std::fs::remove_file(&tmp);
        }
        outcome(target, r);
    }
    let target = with_ext(stem, "csv");
    let r = crate::files::write_atomic(&target, fig.to_csv().as_bytes())
        .map_err(|e| io_err(&target, e));
    outcome(target, r);
    if failed.is_empty() {
        Ok(written)
    } else {
        Err(PlotError::Files { written, failed })
    }
}

/// Names the font family in the SVG text elements and, if asked, embeds the font.
fn finish_svg(svg: &str, embed: bool) -> String {
    let family = if embed {
        "font-family=\"DejaVu Sans Embedded, DejaVu Sans, sans-serif\""
    } else {
        "font-family=\"DejaVu Sans, sans-serif\""
    };
    let svg = svg.replace(&format!("font-family=\"{FAMILY}\""), family);
    if !embed {
        return svg;
    }
    // After the opening <svg ...> tag.
    let Some(at) = svg
        .find("<svg")
        .and_then(|i| svg[i..].find('>').map(|j| i + j + 1))
    else {
        return svg;
    };
    let style = format!(
        "\n<defs><style>@font-face{{font-family:\"DejaVu Sans Embedded\";\
         src:url(data:font/ttf;base64,{})}}</style></defs>",
        base64(FONT)
    );
    format!("{}{style}{}", &svg[..at], &svg[at..])
}

/// Standard base64 with padding.
fn base64(bytes: &[u8]) -> String {
    const ABC: &[u8; 64] = b"ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    let mut out = String::with_capacity(bytes.len().div_ceil(3) * 4);
    for chunk in bytes.chunks(3) {
        let b = [
            chunk[0],
            *chunk.get(1).unwrap_or(&0),
            *chunk.get(2).unwrap_or(&0),
        ];
        let n = u32::from(b[0]) << 16 | u32::from(b[1]) << 8 | u32::from(b[2]);
        for k in 0..4 {
            if k <= chunk.len() {
                out.push(char::from(ABC[(n >> (18 - 6 * k) & 63) as usize]));
            } else {
                out.push('=');
            }
        }
    }
    out
}

/// A legend entry.
#[derive(Clone, Debug, PartialEq)]
struct Entry {
    label: String,
    color: Rgb,
    dash: Option<(Dash, u32)>,
    marker: Option<(Shape, bool)>,
}

fn entries(panel: &Panel) -> Vec<Entry> {
    let lines = panel.lines.iter().filter_map(|l: &Line| {
        l.label.as_ref().map(|label| Entry {
            label: label.clone(),
            color: l.color,
            dash: Some((l.dash, l.width)),
            marker: None,
        })
    });
    let markers = panel.markers.iter().filter_map(|m: &Marker| {
        m.label.as_ref().map(|label| Entry {
            label: label.clone(),
            color: m.color,
            dash: None,
            marker: Some((m.shape, m.filled)),
        })
    });
    lines.chain(markers).collect()
}

fn draw<DB: DrawingBackend>(root: &DrawingArea<DB, Shift>, fig: &Figure) -> Result<(), PlotError>
where
    DB::ErrorType: 'static,
{
    root.fill(&WHITE).map_err(draw_err)?;
    let (_, h) = root.dim_in_pixel();
    let sz = Sizes::for_height(h);
    let body = root
        .titled(
            &shown(&fig.title),
            (FAMILY, sz.title).into_font().color(&BLACK),
        )
        .map_err(draw_err)?;
    let (bw, bh) = body.dim_in_pixel();
    let (main, note) = if fig.note.is_empty() {
        (body, None)
    } else {
        let strip = (sz.note * 1.9) as u32;
        let (m, n) = body.split_vertically(bh.saturating_sub(strip));
        (m, Some(n))
    };
    let (mw, mh) = main.dim_in_pixel();
    let sub = |a: [f64; 4]| {
        let x0 = (a[0] * f64::from(mw)).round() as i32;
        let y0 = (a[1] * f64::from(mh)).round() as i32;
        let w = ((a[2] - a[0]) * f64::from(mw)).round().max(1.0) as u32;
        let h = ((a[3] - a[1]) * f64::from(mh)).round().max(1.0) as u32;
        main.clone().shrink((x0, y0), (w, h))
    };
    let mut figure_entries: Vec<Entry> = Vec::new();
    for panel in &fig.panels {
        let area = sub(panel.area);
        let es = draw_panel(&area, panel, &sz)?;
        if panel.legend == LegendPlace::Figure {
            for e in es {
                if !figure_entries.iter().any(|f| f.label == e.label) {
                    figure_entries.push(e);
                }
            }
        }
    }
    if let Some(a) = fig.legend_area {
        if !figure_entries.is_empty() {
            let area = sub(a);
            // Shrink the font until the entries fit the column (not below 60 %).
            let (aw, _) = area.dim_in_pixel();
            let mut px = sz.legend;
            while px > 0.6 * sz.legend && legend_size(&area, &figure_entries, px).0 + 6 > aw as i32
            {
                px -= 0.5;
            }
            draw_legend(&area, &figure_entries, (0, 40), px, false)?;
        }
    }
    if let Some(n) = note {
        let _ = bw;
        n.draw(&Text::new(
            fig.note.clone(),
            (12, 4),
            (FAMILY, sz.note).into_font().color(&RGBColor(60, 60, 60)),
        ))
        .map_err(draw_err)?;
    }
    Ok(())
}

/// Draws one panel; returns its legend entries.
fn draw_panel<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    panel: &Panel,
    sz: &Sizes,
) -> Result<Vec<Entry>, PlotError>
where
    DB::ErrorType: 'static,
{
    let mut builder = ChartBuilder::on(area);
    if !panel.title.is_empty() {
        builder.caption(shown(&panel.title), (FAMILY, sz.caption).into_font());
    }
    let mut chart = builder
        .margin(8)
        .margin_right(22)
        .x_label_area_size((sz.tick * 3.4) as u32)
        .y_label_area_size((sz.tick * 5.2) as u32)
        .build_cartesian_2d(Coord::new(&panel.x), Coord::new(&panel.y))
        .map_err(draw_err)?;
    let (aw, ah) = area.dim_in_pixel();
    let (nx, ny) = tick_counts(aw, ah, sz);
    let xf = |v: &f64| label(*v, &panel.x, nx);
    let yf = |v: &f64| label(*v, &panel.y, ny);
    chart
        .configure_mesh()
        .x_desc(panel.x.label.as_str())
        .y_desc(panel.y.label.as_str())
        .x_labels(nx)
        .y_labels(ny)
        .x_label_formatter(&xf)
        .y_label_formatter(&yf)
        .label_style((FAMILY, sz.tick).into_font())
        .axis_desc_style((FAMILY, sz.axis_desc).into_font())
        .bold_line_style(RGBColor(228, 228, 228))
        .light_line_style(TRANSPARENT)
        .axis_style(RGBColor(40, 40, 40))
        .draw()
        .map_err(draw_err)?;
    for l in &panel.lines {
        let style = rgb(l.color).stroke_width(l.width);
        let pts = l.points.iter().copied();
        match l.dash {
            Dash::Solid | Dash::Band => chart.draw_series(LineSeries::new(pts, style)).map(|_| ()),
            Dash::Dashed => chart
                .draw_series(DashedLineSeries::new(pts, 10, 6, style))
                .map(|_| ()),
            Dash::Dotted => chart
                .draw_series(DashedLineSeries::new(pts, 3, 5, style))
                .map(|_| ()),
        }
        .map_err(draw_err)?;
    }
    let plot = chart.plotting_area();
    for m in &panel.markers {
        let at = (m.x, m.y);
        draw_marker(plot, at, m.shape, m.filled, m.color, m.size as i32)?;
        if let Some(t) = &m.text {
            let s = m.size as i32;
            let color = rgb(m.color);
            let font = TextStyle::from((FAMILY, sz.legend + 1.0).into_font()).color(&color);
            let (tw, th) = plot.estimate_text_size(t, &font).map_err(draw_err)?;
            let (tw, th) = (tw as i32, th as i32);
            let dx = match m.text_at {
                TextAt::AboveRight | TextAt::BelowRight => s + 3,
                TextAt::AboveLeft | TextAt::BelowLeft => -s - 3 - tw,
            };
            let dy = match m.text_at {
                TextAt::AboveRight | TextAt::AboveLeft => -s - th - 1,
                TextAt::BelowRight | TextAt::BelowLeft => s + 2,
            };
            let backdrop = Rectangle::new(
                [(dx - 2, dy - 1), (dx + tw + 2, dy + th + 1)],
                WHITE.filled(),
            );
            plot.draw(&(EmptyElement::at(at) + backdrop))
                .map_err(draw_err)?;
            plot.draw(&(EmptyElement::at(at) + Text::new(t.clone(), (dx, dy), font)))
                .map_err(draw_err)?;
        }
    }
    let es = entries(panel);
    let corner = match panel.legend {
        LegendPlace::UpperLeft => Some((false, false)),
        LegendPlace::UpperRight => Some((true, false)),
        LegendPlace::LowerLeft => Some((false, true)),
        LegendPlace::LowerRight => Some((true, true)),
        LegendPlace::None | LegendPlace::Figure => None,
    };
    if let (Some((right, bottom)), false) = (corner, es.is_empty()) {
        let pixels = plot.strip_coord_spec();
        let (pw, ph) = pixels.dim_in_pixel();
        let (lw, lh) = legend_size(&pixels, &es, sz.legend);
        let x = if right { pw as i32 - lw - 8 } else { 8 };
        let y = if bottom { ph as i32 - lh - 8 } else { 8 };
        draw_legend(&pixels, &es, (x, y), sz.legend, true)?;
    }
    Ok(es)
}

/// Draws a marker of radius `s` px centred at `at`.
fn draw_marker<DB, CT>(
    area: &DrawingArea<DB, CT>,
    at: CT::From,
    shape: Shape,
    filled: bool,
    color: Rgb,
    s: i32,
) -> Result<(), PlotError>
where
    DB: DrawingBackend,
    DB::ErrorType: 'static,
    CT: CoordTranslate,
    CT::From: Clone,
{
    let c = rgb(color);
    let fill = if filled { c.filled() } else { WHITE.filled() };
    let stroke = c.stroke_width(2);
    let pts: Vec<(i32, i32)> = match shape {
        Shape::Circle => {
            area.draw(&(EmptyElement::at(at.clone()) + Circle::new((0, 0), s, fill)))
                .map_err(draw_err)?;
            return area
                .draw(&(EmptyElement::at(at) + Circle::new((0, 0), s, stroke)))
                .map_err(draw_err);
        }
        Shape::Square => vec![(-s, -s), (s, -s), (s, s), (-s, s)],
        Shape::Triangle => vec![(0, -s - 1), (s + 1, s), (-s - 1, s)],
        Shape::Diamond => vec![(0, -s - 1), (s + 1, 0), (0, s + 1), (-s - 1, 0)],
    };
    let mut closed = pts.clone();
    closed.push(pts[0]);
    area.draw(&(EmptyElement::at(at.clone()) + Polygon::new(pts, fill)))
        .map_err(draw_err)?;
    area.draw(&(EmptyElement::at(at) + PathElement::new(closed, stroke)))
        .map_err(draw_err)
}

fn legend_size<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    es: &[Entry],
    font_px: f64,
) -> (i32, i32) {
    let font = TextStyle::from((FAMILY, font_px).into_font());
    let text_w = es
        .iter()
        .map(|e| {
            area.estimate_text_size(&e.label, &font)
                .map_or(0, |(w, _)| w as i32)
        })
        .max()
        .unwrap_or(0);
    let row = (font_px * 1.6) as i32;
    (text_w + 58, row * es.len() as i32 + 10)
}

/// Draws a legend with its top-left corner at `at` (pixels of `area`).
fn draw_legend<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    es: &[Entry],
    at: (i32, i32),
    font_px: f64,
    boxed: bool,
) -> Result<(), PlotError>
where
    DB::ErrorType: 'static,
{
    let (w, h) = legend_size(area, es, font_px);
    let (x, y) = at;
    if boxed {
        area.draw(&Rectangle::new(
            [(x, y), (x + w, y + h)],
            WHITE.mix(0.9).filled(),
        ))
        .map_err(draw_err)?;
        area.draw(&Rectangle::new(
            [(x, y), (x + w, y + h)],
            RGBColor(150, 150, 150).stroke_width(1),
        ))
        .map_err(draw_err)?;
    }
    let row = (font_px * 1.6) as i32;
    let font = (FAMILY, font_px).into_font().color(&BLACK);
    for (i, e) in es.iter().enumerate() {
        let cy = y + 5 + row * i as i32 + row / 2;
        let (x0, x1) = (x + 8, x + 44);
        if let Some((dash, width)) = e.dash {
            let style = rgb(e.color).stroke_width(width);
            let pts = vec![(x0, cy), (x1, cy)];
            match dash {
                Dash::Solid => area.draw(&PathElement::new(pts, style)),
                Dash::Dashed => area.draw(&DashedPathElement::new(pts, 10, 6, style)),
                Dash::Dotted => area.draw(&DashedPathElement::new(pts, 3, 5, style)),
                Dash::Band => swatch(area, (x0, x1), cy, row, e.color),
            }
            .map_err(draw_err)?;
        }
        if let Some((shape, filled)) = e.marker {
            draw_marker(area, ((x0 + x1) / 2, cy), shape, filled, e.color, 6)?;
        }
        let text_y = cy - (font_px * 0.55) as i32;
        area.draw(&Text::new(e.label.clone(), (x1 + 8, text_y), font.clone()))
            .map_err(draw_err)?;
    }
    Ok(())
}

/// A band's legend sample: a box of its colour from `x0` to `x1`, most of a legend row high
/// whatever the band's width on the map, outlined in grey so that a pale colour shows.
fn swatch<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    (x0, x1): (i32, i32),
    cy: i32,
    row: i32,
    color: Rgb,
) -> Result<(), DrawingAreaErrorKind<DB::ErrorType>> {
    let half = (row * 2 / 5).max(4);
    let corners = [(x0, cy - half), (x1, cy + half)];
    area.draw(&Rectangle::new(corners, rgb(color).filled()))?;
    area.draw(&Rectangle::new(
        corners,
        RGBColor(90, 90, 90).stroke_width(1),
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn base64_matches_rfc_4648_vectors() {
        for (plain, enc) in [
            ("", ""),
            ("f", "Zg=="),
            ("fo", "Zm8="),
            ("foo", "Zm9v"),
            ("foobar", "Zm9vYmFy"),
        ] {
            assert_eq!(base64(plain.as_bytes()), enc);
        }
    }

    #[test]
    fn embedding_puts_the_font_face_inside_the_svg_root() {
        let svg = "<svg width=\"10\" height=\"10\"><text font-family=\"sans-serif\">x</text></svg>";
        let out = finish_svg(svg, true);
        assert!(out.starts_with("<svg width=\"10\" height=\"10\">\n<defs><style>@font-face{"));
        assert!(out.contains("font-family=\"DejaVu Sans Embedded, DejaVu Sans, sans-serif\""));
        assert!(out.ends_with("</text></svg>"));
        assert_eq!(
            finish_svg(svg, false),
            "<svg width=\"10\" height=\"10\"><text font-family=\"DejaVu Sans, sans-serif\">x</text></svg>"
        );
    }

    fn det_k_of_a(dir: &Path) -> (PathBuf, super::super::Rendered) {
        let _ = std::fs::remove_dir_all(dir);
        std::fs::create_dir_all(dir).unwrap();
        let data = crate::analysis::trim_curves::det_k_curve(
            &crate::aircraft::Aircraft::a(),
            2f64.to_radians(),
        )
        .unwrap();
        let stem = dir.join("fig07_det_k");
        let r = crate::plot::det_k(&stem, &data, &PlotStyle::default()).unwrap();
        (stem, r)
    }

    /// Whatever the title (an aircraft's name with markup, quotes, a bell and an escape), the
    /// SVG is well-formed XML and shows the title as the terminal does.
    #[test]
    fn an_svg_is_xml_whatever_its_title() {
        let dir = std::env::temp_dir().join(format!("render-xml-{}", std::process::id()));
        let (_, r) = det_k_of_a(&dir);
        let mut fig = r.figure.clone();
        fig.title = "A <b> & \"q\" 'r' \u{7}\u{1b}[31m \u{3b4}".to_string();
        let stem = dir.join("named");
        render(&stem, &fig, &PlotStyle::default()).unwrap();
        let svg = std::fs::read_to_string(with_ext(&stem, "svg")).unwrap();
        let doc = roxmltree::Document::parse(&svg).unwrap_or_else(|e| panic!("not XML: {e}"));
        assert_eq!(doc.root_element().tag_name().name(), "svg");
        let texts: Vec<&str> = doc.descendants().filter_map(|n| n.text()).collect();
        assert!(
            texts
                .iter()
                .any(|t| t.contains("A <b> & \"q\" 'r' \\u{7}\\u{1b}[31m \u{3b4}")),
            "{texts:?}"
        );
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn the_csv_beside_a_figure_holds_exactly_the_series_drawn() {
        let dir = std::env::temp_dir().join(format!("render-csv-{}", std::process::id()));
        let (stem, r) = det_k_of_a(&dir);
        assert_eq!(r.files.len(), 3, "{:?}", r.files);
        let text = std::fs::read_to_string(with_ext(&stem, "csv")).unwrap();
        let mut rows = text.lines();
        assert_eq!(
            rows.next(),
            Some("panel,panel_title,series,kind,label,x_axis,y_axis,x,y")
        );
        // The drawn series, point by point, from the figure the SVG and PNG were drawn from.
        let mut drawn: Vec<(usize, &str, usize, f64, f64)> = Vec::new();
        for (i, p) in r.figure.panels.iter().enumerate() {
            for (k, l) in p.lines.iter().enumerate() {
                drawn.extend(l.points.iter().map(|(x, y)| (i + 1, "line", k + 1, *x, *y)));
            }
            for (k, m) in p.markers.iter().enumerate() {
                drawn.push((i + 1, "marker", k + 1, m.x, m.y));
            }
        }
        let parsed: Vec<(usize, String, usize, f64, f64)> = rows
            .map(|row| {
                // The last two fields are numbers; the first and third too; labels may be quoted.
                let f: Vec<&str> = row.rsplitn(3, ',').collect();
                let head: Vec<&str> = f[2].splitn(4, ',').collect();
                (
                    head[0].parse().unwrap(),
                    head[3].split(',').next().unwrap().to_string(),
                    head[2].parse().unwrap(),
                    f[1].parse().unwrap(),
                    f[0].parse().unwrap(),
                )
            })
            .collect();
        assert!(drawn.len() > 100, "{}", drawn.len());
        assert_eq!(parsed.len(), drawn.len());
        for (a, b) in parsed.iter().zip(&drawn) {
            assert_eq!((a.0, a.1.as_str(), a.2), (b.0, b.1, b.2));
            assert_eq!(
                (a.3.to_bits(), a.4.to_bits()),
                (b.3.to_bits(), b.4.to_bits())
            );
        }
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn a_file_that_cannot_be_written_is_named_and_the_others_are_written() {
        let dir = std::env::temp_dir().join(format!("render-fail-{}", std::process::id()));
        let (stem, _) = det_k_of_a(&dir);
        let png = with_ext(&stem, "png");
        std::fs::remove_file(&png).unwrap();
        std::fs::create_dir(&png).unwrap();
        let data = crate::analysis::trim_curves::det_k_curve(
            &crate::aircraft::Aircraft::a(),
            2f64.to_radians(),
        )
        .unwrap();
        match crate::plot::det_k(&stem, &data, &PlotStyle::default()) {
            Err(PlotError::Files { written, failed }) => {
                assert_eq!(written, [with_ext(&stem, "svg"), with_ext(&stem, "csv")]);
                assert_eq!(failed.len(), 1);
                assert_eq!(failed[0].0, png);
            }
            other => panic!("{other:?}"),
        }
        let left: Vec<_> = std::fs::read_dir(&dir).unwrap().collect();
        assert_eq!(left.len(), 3, "no temporary left behind");
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
