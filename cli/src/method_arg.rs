//! `--method`: one flag in every render command, offering `auto` (the default: the library
//! chooses, `autostereo::render::auto`) and the methods of that command's primitive (the
//! library's `METHODS` of each), so `--help` lists what works and a method of another
//! primitive is refused by the parser, naming what this one takes.

use std::ffi::OsStr;

use autostereo::render::Method;
use clap::builder::{PossibleValue, TypedValueParser};
use clap::error::ErrorKind;

/// `--method`'s value: `auto` or a method.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum MethodArg {
    /// The fastest method that meets `--min-psnr` (exact ones only without it).
    Auto,
    /// The method named.
    Named(Method),
}

/// Parses `auto` or a [`Method`] name among `methods`, those of `primitive` (plural, as a user says it:
/// "points", "volumes").
#[derive(Clone)]
pub struct MethodParser {
    primitive: &'static str,
    methods: &'static [Method],
}

impl MethodParser {
    pub fn new(primitive: &'static str, methods: &'static [Method]) -> Self {
        Self { primitive, methods }
    }

    /// `a | b | c`, for help texts.
    fn listed(&self, separator: &str) -> String {
        let names: Vec<&str> = self.methods.iter().map(|m| m.name()).collect();
        names.join(separator)
    }
}

impl TypedValueParser for MethodParser {
    type Value = MethodArg;

    fn parse_ref(
        &self,
        cmd: &clap::Command,
        arg: Option<&clap::Arg>,
        value: &OsStr,
    ) -> Result<MethodArg, clap::Error> {
        let mut names: Vec<&str> = vec!["auto"];
        names.extend(self.methods.iter().map(|m| m.name()));
        if value == "auto" {
            return Ok(MethodArg::Auto);
        }
        match value.to_str().and_then(|s| s.parse::<Method>().ok()) {
            Some(method) if self.methods.contains(&method) => Ok(MethodArg::Named(method)),
            Some(method) => Err(cmd.clone().error(
                ErrorKind::InvalidValue,
                format!(
                    "--method {method}: {} do not render by {method}; they render by {}",
                    self.primitive,
                    self.listed(", ")
                ),
            )),
            // clap's own error: the value, the flag and the possible values.
            None => clap::builder::PossibleValuesParser::new(names)
                .parse_ref(cmd, arg, value)
                .and_then(|name| {
                    name.parse::<Method>()
                        .map(MethodArg::Named)
                        .map_err(|e| cmd.clone().error(ErrorKind::InvalidValue, e))
                }),
        }
    }

    fn possible_values(&self) -> Option<Box<dyn Iterator<Item = PossibleValue> + '_>> {
        let auto = PossibleValue::new("auto");
        Some(Box::new(std::iter::once(auto).chain(
            self.methods.iter().map(|m| PossibleValue::new(m.name())),
        )))
    }
}

/// The `--method` argument of a command rendering `primitive`: its parser and its help, which
/// explains only the methods it offers.
pub fn method_arg(
    arg: clap::Arg,
    primitive: &'static str,
    methods: &'static [Method],
) -> clap::Arg {
    let parser = MethodParser::new(primitive, methods);
    let has = |m: Method| methods.contains(&m);
    let duplication: Vec<&str> = Method::DUPLICATION
        .into_iter()
        .filter(|&m| has(m))
        .map(Method::name)
        .collect();
    let mut notes = Vec::new();
    if !duplication.is_empty() {
        notes.push(format!(
            "{} duplicate{} the geometry per view in one draw",
            duplication.join(", "),
            if duplication.len() == 1 { "s" } else { "" }
        ));
    }
    if has(Method::Warp) {
        notes.push("warp renders --references views and synthesises the others".into());
    }
    notes.push("docs/USAGE.md compares them".into());
    let help = format!(
        "Rendering method: auto | {} (auto, the default: the fastest exact one by the cost \
         model of docs/DESIGN.md §10, or of those --min-psnr admits; {})",
        parser.listed(" | "),
        notes.join("; ")
    );
    arg.value_parser(parser).help(help)
}

#[cfg(test)]
mod tests {
    use super::*;
    use clap::{CommandFactory, Parser};

    #[derive(Parser)]
    #[command(mut_arg("method", |a| method_arg(a, "points", &autostereo::points::METHODS)))]
    struct Points {
        #[arg(long, value_parser = MethodParser::new("scenes", &Method::ALL), default_value = "auto")]
        method: MethodArg,
    }

    #[test]
    fn only_the_primitives_methods_parse_and_show() {
        let parse = |m: &str| Points::try_parse_from(["points", "--method", m]);
        assert_eq!(
            parse("tiled").unwrap().method,
            MethodArg::Named(Method::Tiled)
        );
        assert_eq!(parse("auto").unwrap().method, MethodArg::Auto);
        let refused = parse("mrt").err().unwrap().to_string();
        assert!(
            refused.contains("--method mrt: points do not render by mrt")
                && refused.contains("single-pass, n-pass"),
            "{refused}"
        );
        let unknown = parse("fast").err().unwrap().to_string();
        assert!(
            unknown.contains("'fast'") && unknown.contains("possible values"),
            "{unknown}"
        );
        let help = Points::command().render_help().to_string();
        assert!(help.contains("warp renders"), "{help}");
        assert!(!help.contains("mrt"), "{help}");
    }
}
