//! The macro's input as a small AST, parsed with every error collected before failing.
//!
//! Grammar (entries separated by commas, a trailing comma allowed, exactly one entry in the end):
//!
//! ```text
//! input  := entry ("," entry)* ","?
//! entry  := "aircraft" "=" value | "parametric"
//! value  := string literal (a TOML path) | "A" | "B"
//! ```

use proc_macro2::Span;
use syn::ext::IdentExt;
use syn::parse::{Parse, ParseStream};
use syn::{Error, Ident, Lit, LitStr, Token};

/// What every entry may be; the message of an unknown key and of an empty input.
pub const EXPECTED: &str = "expected `aircraft = \"path.toml\"`, `aircraft = A|B` or `parametric`";

/// What the value of `aircraft` may be.
const EXPECTED_VALUE: &str =
    "expected a path string such as `\"aircraft/a.toml\"` or a built-in aircraft `A` or `B`";

/// The parsed input of `roll_criterion!`: where the aircraft data come from.
pub struct Input {
    /// The one source the input names.
    pub source: Source,
}

/// Where the expanded functions take their aircraft data from.
pub enum Source {
    /// `aircraft = "path.toml"`: a TOML file, relative to the invoking crate's directory.
    File(LitStr),
    /// `aircraft = A` or `aircraft = B`: a built-in aircraft of Table A.1.
    Builtin(Builtin),
    /// `parametric`: the data are an argument (`k: &Derivatives`) of every function.
    Parametric,
}

/// The aircraft of Table A.1 that are built into `model`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Builtin {
    /// Aircraft A.
    A,
    /// Aircraft B.
    B,
}

/// One comma-separated entry, with the spans that errors point at.
enum Entry {
    /// `aircraft = value`, with the key.
    Aircraft(Ident, Source),
    /// `parametric`, the key.
    Parametric(Ident),
}

impl Entry {
    fn key(&self) -> &Ident {
        match self {
            Entry::Aircraft(key, _) | Entry::Parametric(key) => key,
        }
    }
}

/// Errors collected while parsing, combined into one `syn::Error` (`serde_derive`'s `Ctxt`).
#[derive(Default)]
struct Errors(Option<Error>);

impl Errors {
    fn push(&mut self, e: Error) {
        match &mut self.0 {
            Some(all) => all.combine(e),
            None => self.0 = Some(e),
        }
    }
}

impl Parse for Input {
    fn parse(input: ParseStream) -> syn::Result<Self> {
        let mut errors = Errors::default();
        let mut entries = Vec::new();
        while !input.is_empty() {
            match parse_entry(input) {
                Ok(entry) => entries.push(entry),
                Err(e) => {
                    errors.push(e);
                    skip_entry(input);
                    continue;
                }
            }
            if input.is_empty() {
                break;
            }
            if input.peek(Token![,]) {
                input.parse::<Token![,]>()?;
            } else {
                errors.push(input.error("unexpected token: expected `,` or the end of the input"));
                skip_entry(input);
            }
        }
        let source = check_entries(entries, &mut errors);
        match (errors.0, source) {
            (Some(e), _) => Err(e),
            (None, Some(source)) => Ok(Input { source }),
            (None, None) => Err(Error::new(
                Span::call_site(),
                format!("{EXPECTED}; the input is empty"),
            )),
        }
    }
}

/// Rejects duplicate and conflicting keys; returns the one source, if any.
fn check_entries(entries: Vec<Entry>, errors: &mut Errors) -> Option<Source> {
    let mut first: Option<Ident> = None;
    let mut source = None;
    for entry in entries {
        let key = entry.key().clone();
        if let Some(prev) = &first {
            let msg = if *prev == key {
                format!("duplicate key `{key}`: give it once")
            } else {
                format!(
                    "`{key}` conflicts with `{prev}`: give either `aircraft = ...` or `parametric`"
                )
            };
            errors.push(Error::new(key.span(), msg));
            continue;
        }
        first = Some(key);
        source = Some(match entry {
            Entry::Aircraft(_, s) => s,
            Entry::Parametric(_) => Source::Parametric,
        });
    }
    source
}

/// Skips the rest of a malformed entry, up to and including the next top-level comma.
fn skip_entry(input: ParseStream) {
    while !input.is_empty() {
        if input.peek(Token![,]) {
            let _ = input.parse::<Token![,]>();
            return;
        }
        if input.parse::<proc_macro2::TokenTree>().is_err() {
            return;
        }
    }
}

/// `aircraft = value` or `parametric`.
fn parse_entry(input: ParseStream) -> syn::Result<Entry> {
    if !input.peek(Ident::peek_any) {
        return Err(input.error(EXPECTED));
    }
    let key = input.call(Ident::parse_any)?;
    match key.to_string().as_str() {
        "parametric" => {
            if input.peek(Token![=]) {
                let eq: Token![=] = input.parse()?;
                return Err(Error::new(
                    eq.span,
                    "`parametric` takes no value: write `parametric` alone",
                ));
            }
            Ok(Entry::Parametric(key))
        }
        "aircraft" => {
            if input.is_empty() || input.peek(Token![,]) {
                return Err(Error::new(
                    key.span(),
                    "missing value for `aircraft`: expected `aircraft = \"path.toml\"` or `aircraft = A|B`",
                ));
            }
            if !input.peek(Token![=]) {
                return Err(input.error("expected `=` after `aircraft`"));
            }
            let eq: Token![=] = input.parse()?;
            if input.is_empty() || input.peek(Token![,]) {
                return Err(Error::new(
                    eq.span,
                    format!("missing value after `aircraft =`: {EXPECTED_VALUE}"),
                ));
            }
            let value = parse_value(input)?;
            Ok(Entry::Aircraft(key, value))
        }
        other => Err(Error::new(
            key.span(),
            format!("unknown key `{other}`: {EXPECTED}"),
        )),
    }
}

/// The value of `aircraft`: a path string or `A`/`B`.
fn parse_value(input: ParseStream) -> syn::Result<Source> {
    if input.peek(LitStr) {
        return Ok(Source::File(input.parse()?));
    }
    if input.peek(Lit) {
        let lit: Lit = input.parse()?;
        let found = match &lit {
            Lit::ByteStr(_) => "a byte string",
            Lit::CStr(_) => "a C string",
            Lit::Byte(_) => "a byte literal",
            Lit::Char(_) => "a character literal",
            Lit::Int(_) => "an integer",
            Lit::Float(_) => "a float",
            Lit::Bool(_) => "a boolean",
            _ => "a literal",
        };
        return Err(Error::new(
            lit.span(),
            format!("{EXPECTED_VALUE}, found {found}"),
        ));
    }
    if input.peek(Ident::peek_any) {
        let name = input.call(Ident::parse_any)?;
        if input.peek(Token![!]) {
            return Err(Error::new(
                name.span(),
                format!(
                    "expected a path string literal, found a macro call `{name}!`: the input is read before macros expand"
                ),
            ));
        }
        return match name.to_string().as_str() {
            "A" => Ok(Source::Builtin(Builtin::A)),
            "B" => Ok(Source::Builtin(Builtin::B)),
            other => Err(Error::new(
                name.span(),
                format!(
                    "unknown built-in aircraft `{other}`: expected `A` or `B`, or a path string such as `\"aircraft/{}.toml\"`",
                    other.to_lowercase()
                ),
            )),
        };
    }
    Err(input.error(EXPECTED_VALUE))
}
