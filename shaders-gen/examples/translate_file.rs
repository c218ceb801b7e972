//! Prints the WGSL for kernel source files: `cargo run --example translate_file -- FILE... [--entry NAME FUNCTION INPUT OUTPUT]`.
fn main() {
    let mut args: Vec<String> = std::env::args().skip(1).collect();
    let mut entries = Vec::new();
    if let Some(pos) = args.iter().position(|a| a == "--entry") {
        let rest: Vec<String> = args.drain(pos..).skip(1).collect();
        if let [name, function, input, output] = rest.as_slice() {
            entries.push(rinshan_shaders_gen::Entry {
                name: name.clone(),
                function: function.clone(),
                input: input.clone(),
                output: output.clone(),
            });
        }
    }
    let mut sources = Vec::new();
    for path in args {
        match std::fs::read_to_string(&path) {
            Ok(text) => sources.push(rinshan_shaders_gen::Source { path, text }),
            Err(e) => {
                eprintln!("{path}: {e}");
                std::process::exit(1);
            }
        }
    }
    match rinshan_shaders_gen::translate(&sources, &entries) {
        Ok(wgsl) => print!("{wgsl}"),
        Err(e) => {
            eprintln!("{e}");
            std::process::exit(1);
        }
    }
}
