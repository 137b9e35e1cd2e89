//! The argument parser's refusals in the command line's words: a flag of another command
//! names the commands that take it (clap only says "unexpected argument"), and a negative
//! number given to a flag that takes none says so (clap reads `-3` as an unknown flag and
//! suggests `-- -3`, which would make it a file name).

use clap::error::{ContextKind, ContextValue, ErrorKind};
use clap::CommandFactory;

/// The message for `error`, clap's refusal of `args`, where one of the cases above applies.
pub fn explain(error: &clap::Error, args: &[String]) -> Option<String> {
    if error.kind() != ErrorKind::UnknownArgument {
        return None;
    }
    let Some(ContextValue::String(arg)) = error.get(ContextKind::InvalidArg) else {
        return None;
    };
    let command = args.get(1).map_or("", String::as_str);
    if arg.starts_with('-') && arg[1..].starts_with(|c: char| c.is_ascii_digit() || c == '.') {
        // The flag before the number is the one given it (clap names "-0" of "-0.5": it
        // reads the rest as more short flags).
        let at = args
            .iter()
            .skip(2)
            .position(|a| a.starts_with(arg.as_str()))?
            + 2;
        let flag = args[..at].last().filter(|f| f.starts_with("--"))?;
        let value = &args[at];
        return Some(format!(
            "{flag} {value}: {flag} takes no negative value (see `autostereo {command} --help`)"
        ));
    }
    let name = arg.strip_prefix("--")?.split('=').next()?;
    let owners = commands_with(name);
    if owners.is_empty() {
        return None;
    }
    let list: Vec<String> = owners.iter().map(|c| format!("`autostereo {c}`")).collect();
    Some(format!(
        "--{name} is not a flag of `autostereo {command}`; {} take{} it (see `autostereo \
         {command} --help` for this command's flags)",
        list.join(", "),
        if owners.len() == 1 { "s" } else { "" }
    ))
}

/// The subcommands that have the long flag `name`.
fn commands_with(name: &str) -> Vec<String> {
    crate::Cli::command()
        .get_subcommands()
        .filter(|c| {
            c.get_arguments()
                .any(|a| a.get_long() == Some(name) && !a.is_hide_set())
        })
        .map(|c| c.get_name().to_string())
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use clap::Parser;

    fn message(args: &[&str]) -> Option<String> {
        let args: Vec<String> = args.iter().map(|a| a.to_string()).collect();
        let error = crate::Cli::try_parse_from(&args).err()?;
        explain(&error, &args)
    }

    #[test]
    fn another_commands_flag_names_the_commands_that_take_it() {
        let text = message(&["autostereo", "points", "--visibility", "exact"]).unwrap();
        assert!(text.contains("`autostereo mesh`"), "{text}");
        assert!(
            text.starts_with("--visibility is not a flag of `autostereo points`"),
            "{text}"
        );
        let text = message(&["autostereo", "volume", "--sort", "cpu"]).unwrap();
        assert!(text.contains("`autostereo gaussians`"), "{text}");
        assert_eq!(message(&["autostereo", "mesh", "--no-such-flag"]), None);
    }

    #[test]
    fn a_negative_number_names_its_flag() {
        let text = message(&["autostereo", "points", "--views", "-3"]).unwrap();
        assert!(
            text.starts_with("--views -3: --views takes no negative value"),
            "{text}"
        );
        let text = message(&["autostereo", "mesh", "--view-scale", "-0.5"]).unwrap();
        assert!(text.starts_with("--view-scale -0.5"), "{text}");
    }
}
