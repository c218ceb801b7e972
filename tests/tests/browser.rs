//! The web page in a real browser (Debian's chromium driven over WebDriver by fantoccini): a person
//! starts a game, plays a whole round by clicking the first legal button (or a playable tile of
//! the hand) each time and sees the round's result; the tile mode switch, the spectate page and
//! the replay page work; no script error is raised. Screenshots go to `target/browser/` for a
//! person to look at. `.ci/run` installs chromium: under `CI=true` a missing browser fails.

use std::path::{Path, PathBuf};
use std::process::{Child, Command, Stdio};
use std::time::{Duration, Instant};

use fantoccini::{Client, ClientBuilder, Locator};
use rinshan_serve::{app, Limits};
use serde_json::{json, Value};

/// The chromedriver child, stopped when the test ends however it ends.
struct Driver(Child);

impl Drop for Driver {
    fn drop(&mut self) {
        let _ = self.0.kill();
        let _ = self.0.wait();
    }
}

fn browser() -> Option<(PathBuf, PathBuf)> {
    let chromium = PathBuf::from(std::env::var("RINSHAN_CHROMIUM").unwrap_or_else(|_| "/usr/bin/chromium".into()));
    let driver =
        PathBuf::from(std::env::var("RINSHAN_CHROMEDRIVER").unwrap_or_else(|_| "/usr/bin/chromedriver".into()));
    if chromium.exists() && driver.exists() {
        return Some((chromium, driver));
    }
    let missing = format!("{} and {}", chromium.display(), driver.display());
    if std::env::var("CI").as_deref() == Ok("true") {
        panic!("the browser test needs {missing} (apt-get install chromium chromium-driver; .ci/run does)");
    }
    eprintln!("browser test skipped: {missing} not found (install chromium chromium-driver)");
    None
}

fn shots() -> PathBuf {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../target/browser");
    std::fs::create_dir_all(&dir).expect("target/browser");
    dir
}

async fn start(chromium: &Path, driver: &Path) -> (Client, Driver, String) {
    let listener = tokio::net::TcpListener::bind("127.0.0.1:0").await.expect("a port");
    let addr = listener.local_addr().expect("an address");
    // The person's game repeats run to run: the server deals every game from one seed (a
    // person cannot choose one).
    // The review budget is the server's smallest useful one: a review must be drawn within the
    // request's timeout (30 s) while the GPU tests' software Vulkan shares CI's two cores.
    let limits = Limits {
        fixed_seed: Some(7),
        review_rollouts: 32,
        ..Limits::default()
    };
    tokio::spawn(async move { axum::serve(listener, app(limits)).await });
    let port = std::net::TcpListener::bind("127.0.0.1:0")
        .and_then(|l| l.local_addr())
        .expect("a free port")
        .port();
    let child = Command::new(driver)
        .arg(format!("--port={port}"))
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .spawn()
        .expect("chromedriver starts");
    let child = Driver(child);
    let profile = std::env::temp_dir().join(format!("rinshan-chromium-{}", std::process::id()));
    let mut caps = serde_json::Map::new();
    caps.insert(
        "goog:chromeOptions".into(),
        json!({
            "binary": chromium,
            "args": [
                "--headless=new", "--no-sandbox", "--disable-gpu", "--disable-dev-shm-usage", "--no-first-run",
                "--disable-background-networking", "--disable-component-update", "--disable-sync", "--disable-quic",
                "--window-size=1400,1000", format!("--user-data-dir={}", profile.display()),
            ],
        }),
    );
    let url = format!("http://127.0.0.1:{port}");
    let deadline = Instant::now() + Duration::from_secs(30);
    let client = loop {
        let connector = hyper_util::client::legacy::connect::HttpConnector::new();
        match ClientBuilder::new(connector)
            .capabilities(caps.clone())
            .connect(&url)
            .await
        {
            Ok(c) => break c,
            Err(e) if Instant::now() > deadline => panic!("chromedriver did not answer: {e}"),
            Err(_) => tokio::time::sleep(Duration::from_millis(200)).await,
        }
    };
    (client, child, format!("http://{addr}"))
}

async fn js(c: &Client, script: &str) -> Value {
    c.execute(script, vec![])
        .await
        .unwrap_or_else(|e| panic!("{script}: {e}"))
}

async fn body_data(c: &Client, key: &str) -> String {
    js(c, &format!("return document.body.dataset.{key} || ''"))
        .await
        .as_str()
        .unwrap_or("")
        .to_string()
}

/// Waits (at most `secs`) until `script` returns true.
async fn until(c: &Client, script: &str, secs: u64) {
    let deadline = Instant::now() + Duration::from_secs(secs);
    while js(c, script).await != Value::Bool(true) {
        if Instant::now() > deadline {
            let page = js(c, "return {errors: window.__errors, error: (document.getElementById('error') || {}).textContent, body: {...document.body.dataset}, url: location.href}").await;
            panic!("timed out waiting for: {script}\npage: {page}");
        }
        tokio::time::sleep(Duration::from_millis(25)).await;
    }
}

async fn screenshot(c: &Client, name: &str) -> PathBuf {
    let png = c.screenshot().await.expect("a screenshot");
    let pixmap = resvg::tiny_skia::Pixmap::decode_png(&png).expect("the screenshot is a PNG");
    // The window is 1400 by 1000; the page's viewport is what is left of it.
    assert!(
        pixmap.width() == 1400 && pixmap.height() > 700,
        "{name}: {}x{}",
        pixmap.width(),
        pixmap.height()
    );
    let colours: std::collections::BTreeSet<[u8; 3]> = pixmap
        .pixels()
        .iter()
        .step_by(97)
        .map(|p| [p.red() & 0xf0, p.green() & 0xf0, p.blue() & 0xf0])
        .collect();
    assert!(colours.len() > 20, "{name} is not blank ({} colours)", colours.len());
    let path = shots().join(name);
    std::fs::write(&path, png).expect("the screenshot is written");
    path
}

/// One browser for every page: two at once would share the machine's two cores with the server.
#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn the_pages_in_a_real_browser() {
    let Some((chromium, driver)) = browser() else { return };
    let (c, _driver, base) = start(&chromium, &driver).await;
    play_a_round(&c, &base).await;
    spectate_and_replay(&c, &base).await;
    c.close().await.expect("the browser closes");
}

async fn play_a_round(c: &Client, base: &str) {
    let c = c.clone();
    c.goto(&format!("{base}/")).await.expect("the page opens");
    until(&c, "return document.body.dataset.ready === '1'", 20).await;
    let no_seed_box = js(
        &c,
        "document.querySelector('[name=mode]').value = 'single';
         document.querySelector('[name=delay]').value = '0';
         return !document.querySelector('[name=seed]');",
    )
    .await;
    assert_eq!(
        no_seed_box,
        Value::Bool(true),
        "a person cannot choose their game's seed"
    );
    c.find(Locator::Id("start"))
        .await
        .expect("a start button")
        .click()
        .await
        .expect("start");
    until(&c, "return !!document.querySelector('#board svg')", 20).await;
    // The person asks for the odds of each discard at their turns.
    c.find(Locator::Id("odds-on"))
        .await
        .expect("the odds switch")
        .click()
        .await
        .expect("odds on");
    let deadline = Instant::now() + Duration::from_secs(150);
    let (mut clicks, mut shot, mut odds) = (0, false, 0);
    loop {
        assert!(
            Instant::now() < deadline && clicks < 400,
            "the round did not end ({clicks} clicks)"
        );
        let phase = body_data(&c, "phase").await;
        if phase == "result" || phase == "over" {
            break;
        }
        if phase != "human" {
            tokio::time::sleep(Duration::from_millis(25)).await;
            continue;
        }
        let step = body_data(&c, "step").await;
        let buttons = c
            .find_all(Locator::Css("#actions button.action"))
            .await
            .expect("buttons");
        // The picture for a person: a call offered (buttons showing), or a few turns in.
        if !shot && (clicks >= 9 || (clicks >= 3 && !buttons.is_empty())) {
            screenshot(&c, "play.png").await;
            shot = true;
        }
        if buttons.is_empty() && odds < 3 {
            // An own turn: the odds table lists the discards, the best first.
            until(
                &c,
                "return document.querySelectorAll('#odds .odds-table tr').length > 1",
                20,
            )
            .await;
            odds += 1;
        }
        let target = match buttons.into_iter().next() {
            Some(b) => b,
            None => c
                .find(Locator::Css("#board .tile.playable"))
                .await
                .expect("a playable tile"),
        };
        target.click().await.expect("a click");
        clicks += 1;
        until(&c, &format!("return document.body.dataset.step !== '{step}'"), 20).await;
    }
    assert!(clicks >= 5, "the person played ({clicks} clicks)");
    assert!(odds >= 1, "the odds were shown at an own turn");
    let result = c.find(Locator::Id("result")).await.expect("the result panel");
    assert!(
        result.is_displayed().await.expect("visible"),
        "the round's result is shown"
    );
    let deltas = js(
        &c,
        "return [...document.querySelectorAll('#result .deltas td:nth-child(2)')].map(td => Number(td.textContent))",
    )
    .await;
    let deltas: Vec<i64> = deltas
        .as_array()
        .expect("deltas")
        .iter()
        .filter_map(Value::as_i64)
        .collect();
    assert_eq!(deltas.len(), 4);
    assert!(
        deltas.iter().sum::<i64>() >= 0 && deltas.iter().any(|&d| d != 0) || deltas.iter().all(|&d| d == 0),
        "{deltas:?}"
    );
    let svg_result = js(&c, "return !!document.querySelector('#board svg .result')").await;
    assert_eq!(svg_result, Value::Bool(true), "the board shows the result panel too");
    screenshot(&c, "result.png").await;
    // The tile mode switch swaps the symbols every board uses.
    c.find(Locator::Id("tiles"))
        .await
        .expect("the switch")
        .select_by_value("ascii")
        .await
        .expect("ascii");
    until(
        &c,
        "return document.body.dataset.tiles === 'ascii' && !!document.querySelector('#sprite symbol#t-1m text')",
        20,
    )
    .await;
    let faces = js(&c, "return document.querySelectorAll('#sprite symbol svg').length").await;
    assert_eq!(faces, json!(0), "ascii tiles draw no face art");
    c.find(Locator::Id("tiles"))
        .await
        .expect("the switch")
        .select_by_value("ja")
        .await
        .expect("ja");
    until(
        &c,
        "return document.body.dataset.tiles === 'ja' && !document.querySelector('#sprite symbol#t-1m text')",
        20,
    )
    .await;
    // A bad move sent from the page is refused and the page says why.
    js(&c, "fetch('/api/games/' + game + '/actions', {method: 'POST', headers: {'Content-Type': 'application/json'}, body: JSON.stringify({action: 0, step: 999999})}).then(r => r.json().then(j => showError(new Error(r.status + ': ' + j.error)))); return true;").await;
    until(&c, "return !document.getElementById('error').hidden && document.getElementById('error').textContent.startsWith('409')", 10).await;
    let errors = js(&c, "return window.__errors").await;
    assert_eq!(errors, json!([]), "no script error");
}

async fn spectate_and_replay(c: &Client, base: &str) {
    let c = c.clone();
    c.goto(&format!("{base}/spectate")).await.expect("the page opens");
    until(&c, "return document.body.dataset.ready === '1'", 20).await;
    // Every rule set is offered; the spectator watches M-League's.
    let rules = js(
        &c,
        "const v = document.querySelector('[name=variant]');
         const names = [...v.options].map((o) => o.value);
         v.value = 'mleague';
         return names;",
    )
    .await;
    // Every rule set the server was built with; a three-player one seats three agents.
    let built: Vec<String> = rinshan_engine::Variant::ALL.iter().map(|v| v.to_string()).collect();
    assert_eq!(rules, json!(built));
    for name in ["red", "no-red", "mjsoul", "mleague", "wrc", "sanma", "mjsoul-sanma"] {
        assert!(built.iter().any(|b| b == name), "{name}: {built:?}");
    }
    let agents = js(
        &c,
        "const v = document.querySelector('[name=variant]');
         const open = () => [...document.querySelectorAll('select.agent')].filter((a) => !a.disabled).length;
         v.value = 'sanma'; v.dispatchEvent(new Event('change'));
         const three = open();
         v.value = 'mleague'; v.dispatchEvent(new Event('change'));
         return [three, open()];",
    )
    .await;
    assert_eq!(
        agents,
        json!([3, 4]),
        "the spectator's form seats as many agents as the rules have seats"
    );
    js(&c, "document.querySelector('[name=delay]').value = '50'; document.querySelector('[name=seed]').value = '3'; return true;").await;
    c.find(Locator::Id("start"))
        .await
        .expect("a watch button")
        .click()
        .await
        .expect("watch");
    // The agents' moves arrive over the event stream without any click.
    until(&c, "return Number(document.body.dataset.step || 0) >= 30", 60).await;
    let hidden = js(
        &c,
        "return document.querySelectorAll('#board .tile[data-zone=hand][data-tile=back]').length",
    )
    .await;
    assert_eq!(hidden, json!(0), "a spectator sees every hand");
    // The page names the rule set played, its description as the tooltip.
    let rules = js(
        &c,
        "const r = document.querySelector('#status .rules'); return r ? [r.textContent, r.title] : null;",
    )
    .await;
    let described = rinshan_engine::Variant::Mleague.description();
    assert!(
        rules[0].as_str().is_some_and(|t| t.starts_with("Rules: mleague (")) && rules[1] == json!(described),
        "{rules}"
    );
    screenshot(&c, "spectate.png").await;
    // The replay page opens a real log and steps through it with the keyboard.
    c.goto(&format!("{base}/replay")).await.expect("the page opens");
    let log = Path::new(env!("CARGO_MANIFEST_DIR")).join("data/tenhou/2016081523gm-00a9-0000-122c42dc.json");
    let log = log.canonicalize().expect("the log");
    c.find(Locator::Id("file"))
        .await
        .expect("a file input")
        .send_keys(&log.display().to_string())
        .await
        .expect("a file");
    c.find(Locator::Id("open"))
        .await
        .expect("an open button")
        .click()
        .await
        .expect("open");
    until(&c, "return !document.getElementById('viewer').hidden", 60).await;
    let frame = c.find(Locator::Id("viewer")).await.expect("the viewer");
    frame.enter_frame().await.expect("into the viewer");
    until(&c, "return document.body.dataset.ready === '1'", 60).await;
    assert_eq!(body_data(&c, "frame").await, "0");
    // Keys go to the focused document: a click on the board focuses the viewer first.
    c.find(Locator::Id("caption"))
        .await
        .expect("the caption")
        .click()
        .await
        .expect("focus");
    c.find(Locator::Css("body"))
        .await
        .expect("the body")
        .send_keys("\u{E014}")
        .await
        .expect("arrow right");
    until(&c, "return document.body.dataset.frame === '1'", 10).await;
    c.find(Locator::Id("next-round"))
        .await
        .expect("a round button")
        .click()
        .await
        .expect("next round");
    until(
        &c,
        "return Number(document.body.dataset.frame) > 10 && document.querySelector('#board svg').dataset.round === '1'",
        10,
    )
    .await;
    c.enter_parent_frame().await.expect("back");
    screenshot(&c, "replay.png").await;
    let errors = js(&c, "return window.__errors").await;
    assert_eq!(errors, json!([]), "no script error");
    // The same log reviewed: seat 1's decisions, the mistakes listed, a click on one shows it.
    js(&c, "document.getElementById('review-seat').value = '1'; return true;").await;
    // The replay's network rests as long as the replay took to draw: the page says so, and the
    // person tries again. The review replaces the replay in the same viewer.
    for _ in 0..20 {
        js(&c, "window.__opened = false; document.getElementById('open').click(); setTimeout(() => { window.__opened = true; }, 50); return true;").await;
        until(
            &c,
            "return window.__opened && !document.getElementById('open').disabled",
            60,
        )
        .await;
        let refused = js(
            &c,
            "const e = document.getElementById('error'); return e.hidden ? '' : e.textContent",
        )
        .await;
        match refused.as_str() {
            Some(m) if m.contains("may start in") => tokio::time::sleep(Duration::from_millis(500)).await,
            Some("") => break,
            _ => panic!("the review was refused: {refused}"),
        }
    }
    let frame = c.find(Locator::Id("viewer")).await.expect("the viewer");
    frame.enter_frame().await.expect("into the viewer");
    until(
        &c,
        "return document.body.dataset.ready === '1' && document.getElementById('candidates') !== null",
        60,
    )
    .await;
    // Laid out, not only loaded: the title and the board take room.
    let sizes = js(
        &c,
        "return [document.querySelector('h1').offsetHeight, document.getElementById('board').offsetHeight]",
    )
    .await;
    assert!(sizes[0].as_u64() > Some(0) && sizes[1].as_u64() > Some(100), "{sizes}");
    let shown = js(
        &c,
        "return [document.querySelectorAll('#candidates tbody tr').length, document.querySelectorAll('#board svg').length,
                 document.querySelectorAll('#rounds tbody tr').length, document.querySelectorAll('#mistakes button').length,
                 document.getElementById('summary').textContent]",
    )
    .await;
    assert!(
        shown[0].as_u64() >= Some(2)
            && shown[1] == json!(1)
            && shown[2].as_u64() >= Some(5)
            && shown[4]
                .as_str()
                .is_some_and(|s| s.ends_with("32 play-outs per decision.")),
        "{shown}"
    );
    if shown[3].as_u64() > Some(0) {
        // The list scrolls beside the board: a click from the script reaches any entry.
        js(&c, "document.querySelector('#mistakes button').click(); return true;").await;
        until(
            &c,
            "return document.getElementById('verdict').textContent.startsWith('Mistake')",
            10,
        )
        .await;
    }
    c.enter_parent_frame().await.expect("back");
    // The viewer repaints after its page has drawn: bring it into view, then the picture.
    js(&c, "document.getElementById('viewer').scrollIntoView(); return true;").await;
    tokio::time::sleep(Duration::from_millis(500)).await;
    screenshot(&c, "review.png").await;
    let errors = js(&c, "return window.__errors").await;
    assert_eq!(errors, json!([]), "no script error");
}
