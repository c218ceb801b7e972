//! `rinshan reference`: the command's own reference, generated from its clap definitions so it
//! cannot drift from them: Markdown for the guide (docs/cli.md, which a test holds equal to this
//! output) or a man page.

use std::io::Write;

use crate::error::CliError;

#[derive(clap::Args)]
pub struct Args {
    /// A man page (roff) instead of Markdown
    #[arg(long)]
    man: bool,
}

pub fn run(args: Args, command: clap::Command) -> Result<(), CliError> {
    let mut out = std::io::stdout().lock();
    if args.man {
        clap_mangen::Man::new(command)
            .render(&mut out)
            .map_err(|e| CliError::failure(format!("writing the man page: {e}")))?;
        return Ok(());
    }
    let options = clap_markdown::MarkdownOptions::new()
        .title("Command-line reference".to_string())
        .show_footer(false);
    let page = clap_markdown::help_markdown_command_custom(&command, &options);
    out.write_all(page.as_bytes())
        .map_err(|e| CliError::failure(format!("writing the reference: {e}")))
}
