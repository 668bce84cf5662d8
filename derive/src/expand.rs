//! From the parsed input to tokens: load the aircraft, call the emitter of `model`, and make
//! cargo track the TOML file.

use crate::input::{Builtin, Input, Source};
use model::aircraft::{self, Aircraft, AircraftError};
use proc_macro2::TokenStream;
use quote::quote;
use std::path::{Path, PathBuf};
use syn::{Error, LitStr};

/// Read before `CARGO_MANIFEST_DIR` when set: the directory relative paths are resolved against.
///
/// A test hook (dtolnay/trybuild#202): trybuild compiles UI tests in a crate of its own under
/// `target/`, so this crate's UI test points the macro back at `derive/`.
pub const MANIFEST_DIR_OVERRIDE: &str = "ROLL_CRITERION_MANIFEST_DIR";

/// The items `roll_criterion!` expands to.
pub fn expand(input: Input) -> syn::Result<TokenStream> {
    Ok(match input.source {
        Source::Parametric => model::emit::macro_items(None),
        Source::Builtin(Builtin::A) => model::emit::macro_items(Some(&Aircraft::a())),
        Source::Builtin(Builtin::B) => model::emit::macro_items(Some(&Aircraft::b())),
        Source::File(lit) => {
            let (ac, path) = load(&lit)?;
            let tracked = LitStr::new(&path, lit.span());
            let mut items = model::emit::macro_items(Some(&ac));
            // Recompile the invoking crate when the TOML file changes.
            items.extend(quote!(
                const _: &[u8] = ::core::include_bytes!(#tracked);
            ));
            items
        }
    })
}

/// Loads the aircraft file the literal names, relative to the invoking crate's directory;
/// returns it with the file's absolute path. Errors point at the literal and name the file as
/// written.
fn load(lit: &LitStr) -> syn::Result<(Aircraft, String)> {
    let err = |msg: String| Error::new(lit.span(), msg);
    let written = lit.value();
    let dir = std::env::var_os(MANIFEST_DIR_OVERRIDE)
        .or_else(|| std::env::var_os("CARGO_MANIFEST_DIR"))
        .ok_or_else(|| {
            err(format!(
                "cannot resolve `{written}`: CARGO_MANIFEST_DIR is not set (expand the macro under cargo)"
            ))
        })?;
    let path = Path::new(&dir).join(&written);
    let text = std::fs::read_to_string(&path).map_err(|source| {
        let e = AircraftError::Io {
            path: PathBuf::from(&written),
            source,
        };
        err(format!(
            "{e}; relative paths start at the invoking crate's directory (CARGO_MANIFEST_DIR)"
        ))
    })?;
    let ac = aircraft::parse(&text, &written).map_err(|e| err(e.to_string()))?;
    let abs = path.canonicalize().unwrap_or(path);
    let abs = abs
        .to_str()
        .ok_or_else(|| err(format!("the path of `{written}` is not valid UTF-8")))?;
    Ok((ac, abs.to_owned()))
}
