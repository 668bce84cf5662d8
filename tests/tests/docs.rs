//! The README and the user's guide hold together: every relative link and image of README.md and
//! of the Markdown pages under docs/ names a file that exists and, with a `#fragment`, a heading
//! of that page (the anchor GitHub and mdBook give it); and every page under docs/ is a chapter
//! of the mdBook's docs/SUMMARY.md, so that the rendered guide has it too.

use markdown::mdast::Node;
use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};

fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("..")
}

/// The Markdown files under `dir`, in order.
fn markdown_under(dir: &Path, files: &mut Vec<PathBuf>) {
    let mut entries: Vec<PathBuf> = std::fs::read_dir(dir)
        .unwrap_or_else(|e| panic!("{}: {e}", dir.display()))
        .map(|entry| entry.unwrap().path())
        .collect();
    entries.sort();
    for path in entries {
        if path.is_dir() {
            markdown_under(&path, files);
        } else if path.extension().is_some_and(|ext| ext == "md") {
            files.push(path);
        }
    }
}

/// README.md and every page of the guide.
fn pages() -> Vec<PathBuf> {
    let mut files = vec![root().join("README.md")];
    markdown_under(&root().join("docs"), &mut files);
    files
}

/// The anchor GitHub and mdBook give a heading: lower case, letters, digits, `-` and `_` kept,
/// white space made `-`, anything else dropped.
fn anchor(heading: &str) -> String {
    heading
        .chars()
        .filter_map(|c| {
            if c.is_alphanumeric() || c == '-' || c == '_' {
                Some(c.to_lowercase().next().unwrap())
            } else if c.is_whitespace() {
                Some('-')
            } else {
                None
            }
        })
        .collect()
}

/// A Markdown page's link and image targets, and its headings' anchors (a repeated heading's
/// second anchor ends in `-1`, its third in `-2`, as GitHub and mdBook number them).
fn links_and_anchors(text: &str) -> (Vec<String>, BTreeSet<String>) {
    let tree = markdown::to_mdast(text, &markdown::ParseOptions::gfm())
        .unwrap_or_else(|e| panic!("not Markdown: {e}"));
    let mut links = Vec::new();
    let mut headings = Vec::new();
    walk(&tree, &mut links, &mut headings);
    let mut anchors = BTreeSet::new();
    let mut seen: BTreeMap<String, usize> = BTreeMap::new();
    for heading in headings {
        let base = anchor(&heading);
        let count = seen.entry(base.clone()).or_insert(0);
        anchors.insert(match *count {
            0 => base,
            n => format!("{base}-{n}"),
        });
        *count += 1;
    }
    (links, anchors)
}

/// The link and image targets (reference definitions included) and the heading texts under
/// `node`, in document order.
fn walk(node: &Node, links: &mut Vec<String>, headings: &mut Vec<String>) {
    match node {
        Node::Link(link) => links.push(link.url.clone()),
        Node::Image(image) => links.push(image.url.clone()),
        Node::Definition(definition) => links.push(definition.url.clone()),
        Node::Heading(_) => headings.push(node.to_string()),
        _ => {}
    }
    for child in node.children().into_iter().flatten() {
        walk(child, links, headings);
    }
}

/// Whether a link leaves the repository (a web address, mail).
fn external(target: &str) -> bool {
    target.contains("://") || target.starts_with("mailto:")
}

/// The relative links of the page `path` (text `text`) that name no file, or no heading of
/// the page they name.
fn broken_links(path: &Path, text: &str) -> Vec<String> {
    let dir = path.parent().unwrap();
    let (links, own_anchors) = links_and_anchors(text);
    let mut broken = Vec::new();
    for link in links.iter().filter(|l| !external(l)) {
        let (file, fragment) = link.split_once('#').unwrap_or((link, ""));
        let target = if file.is_empty() {
            path.to_path_buf()
        } else {
            dir.join(file)
        };
        if !target.exists() {
            broken.push(format!("{link}: no file {}", target.display()));
            continue;
        }
        if fragment.is_empty() {
            continue;
        }
        let anchors = if file.is_empty() {
            own_anchors.clone()
        } else if target.extension().is_some_and(|ext| ext == "md") {
            links_and_anchors(&std::fs::read_to_string(&target).unwrap()).1
        } else {
            BTreeSet::new()
        };
        if !anchors.contains(fragment) {
            broken.push(format!("{link}: no heading #{fragment} in {file}"));
        }
    }
    broken
}

#[test]
fn every_relative_link_and_anchor_of_the_readme_and_the_guide_resolves() {
    let mut broken = Vec::new();
    for page in pages() {
        let text = std::fs::read_to_string(&page).unwrap();
        let name = page
            .strip_prefix(root())
            .unwrap_or(&page)
            .display()
            .to_string();
        for link in broken_links(&page, &text) {
            broken.push(format!("{name}: {link}"));
        }
    }
    assert!(broken.is_empty(), "broken links:\n{}", broken.join("\n"));
}

#[test]
fn every_page_of_the_guide_is_a_chapter_of_its_summary() {
    let docs = root().join("docs");
    let summary = std::fs::read_to_string(docs.join("SUMMARY.md")).unwrap();
    let chapters: BTreeSet<PathBuf> = links_and_anchors(&summary)
        .0
        .iter()
        .map(|link| docs.join(link))
        .collect();
    let mut files = Vec::new();
    markdown_under(&docs, &mut files);
    let missing: Vec<String> = files
        .iter()
        .filter(|f| f.file_name().unwrap() != "SUMMARY.md" && !chapters.contains(*f))
        .map(|f| f.display().to_string())
        .collect();
    assert!(
        missing.is_empty(),
        "pages missing from docs/SUMMARY.md:\n{}",
        missing.join("\n")
    );
}

/// The check itself: a missing file, a missing heading and a heading's repeated anchor.
#[test]
fn the_link_check_sees_a_missing_file_and_a_missing_heading() {
    let dir = std::path::Path::new(env!("CARGO_TARGET_TMPDIR"))
        .join(format!("docs-links-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    std::fs::write(
        dir.join("b.md"),
        "# What `analyze` prints\n\n## Routes\n\n## Routes\n",
    )
    .unwrap();
    let page = dir.join("a.md");
    let text = "# The paper's aircraft A\n\n[ok](b.md#what-analyze-prints) [ok](b.md#routes-1) \
                [ok](#the-papers-aircraft-a) [ok](https://example.org/x.md#y) ![ok](b.md)\n\
                [gone](c.md) [no heading](b.md#routes-2) [no anchor](#nowhere)\n";
    std::fs::write(&page, text).unwrap();
    let broken = broken_links(&page, text);
    std::fs::remove_dir_all(&dir).unwrap();
    assert_eq!(broken.len(), 3, "{broken:#?}");
    assert!(broken[0].starts_with("c.md: no file"), "{broken:#?}");
    assert!(
        broken[1].starts_with("b.md#routes-2: no heading"),
        "{broken:#?}"
    );
    assert!(broken[2].starts_with("#nowhere: no heading"), "{broken:#?}");
}
