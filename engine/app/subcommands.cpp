// The subcommand table: the single list `squawk --help` prints and dispatches.
#include "app/cli.h"
#include "app/subcommands.h"

namespace squawk::app {

const std::vector<Subcommand>& subcommands() {
  static const std::vector<Subcommand> table = {
      {"demo", "demo                      the team loop: agent -> English -> translator -> simulator",
       "usage: squawk demo [--policy mlp|gpt2] [--checkpoint FILE] [--seed N] [--record FILE.jsonl]\n"
       "                   [--svg FILE.svg] [--scenario FILE.lua] [--advisory FILE.lua] [--quiet]\n\n"
       "Runs one conflict episode of the paper's HorizontalCR evaluation setup\n"
       "(scenarios/horizontal_cr.lua) as a team: the deconfliction agent (the shipped\n"
       "trained MLP, or with --policy gpt2 the shipped fine-tuned tiny GPT-2 prompt\n"
       "policy) decides on the environment's observation; prompts/advisory.lua\n"
       "says the decision in controller English (\"KL001, turn right heading 045\");\n"
       "the offline translator turns that into TrafScript; the simulator's command\n"
       "stack executes it and flies the traffic, with conflict detection on. Steps\n"
       "without a predicted conflict steer to the waypoint (logged as autopilot).\n"
       "Every hop is logged with sim time; a summary follows: conflicts met and\n"
       "resolved, losses of separation, extra track length, waypoint reached.\n"
       "  --seed N        the episode: the first of seed N's sequence that needs the agent\n"
       "  --record FILE   write the episode as JSON lines (for `squawk render`)\n"
       "  --svg FILE      draw the episode (Fig. 2 style)\n"
       "Exit 1 when an advisory could not be translated or executed.\n",
       cmd_demo},
      {"run", "run FILE.lua [ARGS...]   run a Lua script (the script sees ARGS as `arg`)",
       "usage: squawk run FILE.lua [ARGS...] [--seed N] [--unsafe] [--out DIR]\n"
       "                 [--max-instructions N] [--navdata DIR]\n\n"
       "Runs a Lua script in squawk's sandbox. The script sees its arguments in the\n"
       "global table `arg` (arg[0] is the script path) and the engine as `squawk`.\n"
       "Flags squawk knows are taken wherever they stand; everything else goes to\n"
       "the script, and `--` passes the rest to the script untouched.\n\n"
       "  --seed N               seed of the engine RNG (math.random too); default 0\n"
       "  --unsafe               lift the sandbox: os, io, package.loadlib, C modules\n"
       "  --out DIR              the one folder the script may write files into\n"
       "  --max-instructions N   stop a script after N Lua VM instructions\n"
       "                         (default 500000000; 0 = no limit)\n"
       "  --navdata DIR          BlueSky navdata folder (airports.dat, fix.dat, nav.dat)\n",
       cmd_run},
      {"test", "test [DIR|FILE...]       run Lua regression scripts (default tests/lua/)",
       "usage: squawk test [DIR|FILE...] [--seed N] [--max-instructions N] [--navdata DIR]\n\n"
       "Runs every *.lua file in the given folders (default tests/lua/), each in a\n"
       "fresh sandboxed VM. Scripts use the assertion API:\n"
       "  check(cond, [msg])            passes when cond is truthy\n"
       "  check_eq(got, want, [msg])    passes when got == want\n"
       "  check_near(got, want, tol, [msg])  passes when |got - want| <= tol\n"
       "A failed check prints file:line and the values; the script goes on. A script\n"
       "passes when it ends without error and with no failed check. The last line\n"
       "is `N passed, N failed`; the exit code is 1 when any script failed.\n",
       cmd_test},
      {"gpt2", "gpt2 info|generate|logits|bench DIR|tiny   the GPT-2 model on the CPU",
       "usage: squawk gpt2 info DIR\n"
       "       squawk gpt2 generate DIR \"PROMPT\" [--max-tokens N] [--top-k K] [--seed N]\n"
       "       squawk gpt2 logits DIR \"TEXT\" [--json]\n"
       "       squawk gpt2 bench [--json] [--tiny] [--seq T] [--batch 1,8] [--threads 1,2]\n"
       "                         [--seconds S]\n"
       "       squawk gpt2 train-bpe OUT_DIR FILE... [--merges N]\n"
       "       squawk gpt2 init OUT_DIR [--vocab DIR] [--layers N] [--heads N] [--width N]\n"
       "                        [--context N] [--seed N]\n\n"
       "DIR is a Hugging Face GPT-2 folder (config.json, model.safetensors in F32,\n"
       "F16 or BF16, vocab.json + merges.txt) or the word `tiny`: a random 2-layer,\n"
       "64-wide model over the byte-level vocabulary, seeded by --seed (default 0).\n\n"
       "  info        sizes of the model and its tokenizer, and the matrix backend\n"
       "  generate    continue PROMPT token by token through the KV cache, sampling\n"
       "              among the K most likely tokens (default 40; 1 = greedy) for up\n"
       "              to N tokens (default 32) or until <|endoftext|>\n"
       "  logits      the tokens of TEXT and the logits at its last position; --json\n"
       "              prints {\"tokens\": [...], \"logits\": [...]}\n"
       "  bench       forward throughput of GPT-2 small (random weights, T = 256,\n"
       "              B = 1 and 8, 1 and 2 threads) against the machine's measured\n"
       "              sgemm peak, and forward+backward time per prompt with the last\n"
       "              block trainable; --json prints gflops, peak_gflops,\n"
       "              fraction_of_peak and every run; --tiny uses the tiny model\n"
       "  train-bpe   learn N byte-level BPE merges (default 256) on the text files\n"
       "              and write vocab.json + merges.txt to OUT_DIR\n"
       "  init        write a random GPT-2 folder (GPT-2's initialisation; default the\n"
       "              tiny shape) over the vocabulary of --vocab DIR or the bytes\n",
       cmd_gpt2},
      {"render", "render EPISODE.jsonl|SCENARIO.lua|SCENARIO.scn   draw an episode or traffic as SVG",
       "usage: squawk render EPISODE.jsonl [--episode K] [--frame N] [--size PX]\n"
       "                     [--out FILE.svg|-]\n"
       "       squawk render SCENARIO.lua [--seed N] [--size PX] [--out FILE.svg|-]\n"
       "       squawk render SCENARIO.scn [--at T] [--navdata DIR] [--size PX] [--out FILE.svg|-]\n\n"
       "Draws a recorded episode top-down, north up (the paper's Fig. 2): the\n"
       "ownship's and intruders' tracks, each intruder's separation circle (red\n"
       "while the ownship is inside), the waypoint with its capture circle, the\n"
       "ownship's closest approach to any intruder so far, a scale bar and a north\n"
       "arrow; the caption gives the time and the frame. Episodes are recorded by\n"
       "`squawk demo --record FILE` and `squawk eval --record FILE`.\n"
       "With a scenario file (.lua), draws the start of its evaluation episode for\n"
       "the seed. With a BlueSky scenario (.scn), runs it to T seconds (default 0)\n"
       "and draws every aircraft with its track, flight level and speed, red while\n"
       "in a detected conflict; commands that fail are summarised on stderr.\n"
       "  --episode K draw episode K of the recording (default: the first one)\n"
       "  --frame N   draw aircraft where they were at recorded frame N, 0 to the\n"
       "              last (default: the last); other numbers are errors\n"
       "  --at T      .scn: the time drawn [s], 0 to 86400\n"
       "  --navdata DIR  .scn: BlueSky navdata (default $SQUAWK_NAVDATA)\n"
       "  --size PX   picture side, 100 to 8000 (default 720)\n"
       "  --out FILE  output path (default: the input with .svg; `-` = stdout)\n"
       "For a PNG: rsvg-convert -o out.png out.svg (Debian package librsvg2-bin).\n",
       cmd_render},
      {"plot", "plot RUN_DIR|FILE.csv...   draw training curves as SVG (Fig. 3 style)",
       "usage: squawk plot RUN_DIR|FILE.csv... [--out FILE.svg|-]\n\n"
       "Reads the CSV logs training runs write (columns episodes and\n"
       "eval_success_rate / eval_mean_reward, or success_rate / mean_reward)\n"
       "and draws success rate and mean reward against episodes trained (from 0),\n"
       "one line per CSV file: every CSV in each RUN_DIR, and each FILE.csv named.\n"
       "Default output: RUN_DIR/curves.svg or FILE.svg for one argument,\n"
       "curves.svg in the current folder for several.\n",
       cmd_plot},
      {"rag", "rag search QUERY | rag eval CORPUS.tsv   command retrieval (BM25)",
       "usage: squawk rag search QUERY... [--k N] [--text] [--notes FILE] [--no-notes]\n"
       "       squawk rag eval CORPUS.tsv [--k N] [--misses] [--notes FILE] [--no-notes]\n\n"
       "Ranks the TrafScript commands for an English request with BM25 over the\n"
       "command registry's documentation plus the retrieval notes in\n"
       "scripts/translate/phraseology.txt (NAME: words per line).\n"
       "`search` prints the best N commands with their scores (--text adds the\n"
       "documents). `eval` reads a translator corpus (id, setup, utterance,\n"
       "expected, category) and prints Recall@1 and Recall@N: the share of cases\n"
       "whose expected commands are all among the first N retrieved. ASK cases\n"
       "are counted apart; --misses lists the cases retrieval got wrong.\n\n"
       "  --k N          how many documents to retrieve (default 5)\n"
       "  --notes FILE   retrieval notes to use instead of the shipped ones\n"
       "  --no-notes     the registry documentation alone\n",
       cmd_rag},
      {"repl", "repl [SCENARIO.scn]        talk to the simulation in English (or !TrafScript)",
       "usage: squawk repl [SCENARIO.scn] [--clock X] [--mode offline|single|multi]\n"
       "                   [--llm-url URL] [--llm-model NAME] [--llm-api ollama|openai]\n"
       "                   [--seed N] [--navdata DIR]\n\n"
       "An interactive session on one simulation. Each English line goes through\n"
       "the translation graph; the TrafScript it produced is shown, run, and the\n"
       "aircraft it touched are listed (current -> selected values, route). Lines\n"
       "starting with ! are TrafScript as typed. A question back (?) is answered by\n"
       "the next line; `cancel` drops it. Loading a scenario summarises its failed\n"
       "commands as `squawk scn` does.\n"
       "The clock is stopped (HOLD) unless --clock X (X times real time) or OP\n"
       "starts it; HOLD stops it; FF SECONDS runs at once. While time moves,\n"
       "conflicts and losses of separation are reported as they start and end,\n"
       "with ECHO lines and failing scenario commands.\n"
       "  :state        the clock, the aircraft, the conflicts (tLOS, tCPA, dCPA)\n"
       "  :run SECONDS  advance now      :clock X|off  running clock on / off\n"
       "  :trace        the graph's path for the last request\n"
       "  :mode M       switch the translator      :help, :quit\n"
       "On a terminal: readline history, Tab completes callsigns and commands,\n"
       "Ctrl-C clears the line, Ctrl-D leaves. From a pipe there is no banner or\n"
       "prompt, only replies.\n\n"
       "The LLM comes from --llm-url/--llm-model/--llm-api or SQUAWK_LLM_URL,\n"
       "SQUAWK_LLM_MODEL, SQUAWK_LLM_API; with none (or when the server fails) the\n"
       "offline grammar translates. The default mode is multi with an LLM, else\n"
       "offline.\n",
       cmd_repl},
      {"serve", "serve [SCENARIO.scn]       the radar scope in a browser, simulation running live",
       "usage: squawk serve [SCENARIO.scn] [--port N] [--host ADDR] [--speed X] [--paused]\n"
       "                    [--mode offline|single|multi] [--seed N] [--navdata DIR] [--web DIR]\n"
       "                    [--agent [--policy mlp|gpt2] [--checkpoint FILE] [--auto]]\n\n"
       "Serves a radar scope at http://127.0.0.1:8080/ while the simulation runs live\n"
       "on the server: real time x DTMULT (--speed sets it; HOLD, OP and FF work as\n"
       "commands). The page shows the traffic, conflicts and their closest points of\n"
       "approach, a traffic list, and a command line for English (the REPL's\n"
       "translation graph) or !TrafScript. Several browsers may watch at once.\n\n"
       "  --port N      listen port (0: any free port; the URL is printed)\n"
       "  --host ADDR   listen address; default 127.0.0.1 (this machine only)\n"
       "  --paused      start in HOLD\n"
       "  --web DIR     serve the page from DIR instead of the shipped web/\n"
       "  --agent       the AI teammate: the demo's episode of --seed (KL001 and its\n"
       "                intruders) with the deconfliction agent, whose advisories\n"
       "                the page offers to accept or reject (the log says who decided)\n"
       "  --policy K    the agent: mlp (default) or gpt2; --checkpoint FILE another one\n"
       "  --auto        execute the agent's advisories without asking (the page can\n"
       "                switch this on and off)\n\n"
       "HTTP API (JSON): GET /api/state, GET /api/stream (server-sent events, 10 Hz),\n"
       "POST /api/command {\"text\": ...}, POST /api/advisory {\"id\", \"decision\"},\n"
       "POST /api/auto {\"on\"}, GET /api/navdata?south=&north=&west=&east=.\n",
       cmd_serve},
      {"llm", "llm chat TEXT | llm embed TEXT   ask the configured LLM server directly",
       "usage: squawk llm chat TEXT... [--stream] [--system TEXT] [--llm-url URL]\n"
       "                  [--llm-model NAME] [--llm-api ollama|openai] [--temperature T]\n"
       "                  [--seed N] [--context TOKENS] [--timeout SECONDS] [--max-reply-mb MB]\n"
       "       squawk llm embed TEXT... [same server flags]\n\n"
       "Sends one request to the LLM server the translator would use, to check the\n"
       "configuration: `chat` prints the reply (--stream prints it as it arrives)\n"
       "and, on stderr, the server, token counts and attempts; `embed` prints the\n"
       "size of each embedding. The server comes from the flags or SQUAWK_LLM_URL,\n"
       "SQUAWK_LLM_MODEL, SQUAWK_LLM_API. A URL ending in /v1 speaks the\n"
       "OpenAI-compatible API (llama.cpp server, vLLM, Ollama's /v1); any other\n"
       "URL Ollama's native API. Temperature, seed and context size are sent with\n"
       "every request; transport failures and 5xx replies are retried with backoff.\n",
       cmd_llm},
      {"scn", "scn FILE.scn               run a BlueSky scenario headless and summarise it",
       "usage: squawk scn FILE.scn [--until SECONDS] [--navdata DIR] [--dump-json] [--seed N]\n"
       "                           [--max-wall SECONDS]\n"
       "       squawk scn DIR --conformance [--max-time SECONDS] [--navdata DIR]\n\n"
       "Loads a BlueSky scenario file and runs it without display until every timed\n"
       "command has run (at most --max-time, default 3600 s of sim time) or until\n"
       "--until. Prints ECHO output and failures as they happen, then a summary:\n"
       "commands executed, commands skipped because squawk lacks them (display and\n"
       "plugin commands such as PAN, ZOOM, SWRAD), failures grouped by reason,\n"
       "aircraft, conflicts and losses of separation. Exit code 1 when a command\n"
       "failed.\n\n"
       "  --navdata DIR   BlueSky navdata (airports.dat, fix.dat, nav.dat); default\n"
       "                  $SQUAWK_NAVDATA. Without it, named places are errors.\n"
       "  --dump-json     print only the final state as JSON: simt and per aircraft\n"
       "                  id, type, lat, lon, alt_ft, hdg_deg, tas_kt, cas_kt, gs_kt,\n"
       "                  vs_fpm (failed commands go to stderr)\n"
       "  --max-wall S    stop with an error after S seconds of wall-clock time\n"
       "                  (default 600; 0 = no limit)\n"
       "  --conformance   run every file under DIR and print Markdown tables of the\n"
       "                  totals, skipped commands and failure reasons\n",
       cmd_scn},
      {"commands", "commands [NAME] [--json]   list the TrafScript commands (the registry)",
       "usage: squawk commands [NAME] [--json]\n\n"
       "Prints the TrafScript command registry: every command's usage line, or the\n"
       "full help of one command (aliases, what it does, examples). --json prints\n"
       "the whole registry as a JSON array of {name, aliases, args, usage, help,\n"
       "examples}; the translator and its retrieval index read this.\n",
       cmd_commands},
      {"translate", "translate \"TEXT\" [--scenario FILE]  English -> TrafScript with the offline grammar",
       "usage: squawk translate \"TEXT\" [--scenario FILE] [--setup \"CMD ; CMD\"] [--jsonl]\n"
       "       squawk translate --tsv CORPUS.tsv\n\n"
       "Translates a controller's or experimenter's request into TrafScript with the\n"
       "built-in grammar (no language model) and prints the commands, separated by\n"
       "' ; ', or the question it asks back when a value is missing. Relative\n"
       "instructions and spoken callsigns are resolved against the traffic that the\n"
       "scenario (its time-0 commands) and the setup commands create; with either\n"
       "given, exit code 1 when a produced command does not validate against it.\n\n"
       "  --scenario FILE  a .scn file whose time-0 commands set up the traffic\n"
       "  --setup CMDS     TrafScript commands run first, separated by ';'\n"
       "  --jsonl          print {\"output\": ...} or {\"ask\": ...} as one JSON line\n"
       "  --tsv CORPUS     run each case of a corpus (id setup utterance expected\n"
       "                   category) on a fresh simulation after its setup and print\n"
       "                   one JSON line per case: {\"id\", \"output\"} or {\"id\", \"ask\"}\n",
       cmd_translate},
      {"eval-translate", "eval-translate CORPUS.tsv [--mode M]  translation accuracy per category",
       "usage: squawk eval-translate CORPUS.tsv [--mode offline|single|multi] [--failures] [--json]\n\n"
       "Translates every case of a corpus on a fresh simulation after the case's\n"
       "setup and scores it with the corpus rules (shared/corpora/README.md):\n"
       "aliases folded, altitudes within 50 ft, headings modulo 360, and so on. Prints\n"
       "cases, correct answers and accuracy per category and overall.\n\n"
       "  --mode offline   the built-in grammar (default)\n"
       "  --mode single    the Lua translation graph with one LLM call per request\n"
       "  --mode multi     the Lua translation graph with its multi-agent pipeline;\n"
       "                   single and multi need SQUAWK_LLM_URL (an LLM server)\n"
       "  --failures       list the cases it got wrong with what it produced\n"
       "  --json           print the figures as JSON\n",
       cmd_eval_translate},
      {"train", "train SCENARIO.lua --out DIR   train the conflict-resolution MLP policy",
       "usage: squawk train SCENARIO.lua --out DIR [--policy mlp] [--episodes N] [--seed N]\n"
       "                    [--estimator vpg|improved] [--lr X] [--envs N] [--eval-every N]\n"
       "                    [--eval-episodes N] [--resume] [--quiet]\n\n"
       "Trains the MLP policy of a conflict-resolution scenario (scenarios/*.lua) by\n"
       "policy gradient with Adam, on the scenario's training settings, evaluating\n"
       "it on the scenario's evaluation settings every --eval-every episodes. The\n"
       "scenario's train table gives the defaults; flags override them. Writes into\n"
       "DIR a checkpoint (checkpoint.ckpt, replaced atomically after each\n"
       "evaluation), log.csv (one row per evaluation interval), best.ckpt (the\n"
       "policy with the best evaluation success so far) and, at the end,\n"
       "policy.ckpt (the final policy alone). Evaluations during training use the\n"
       "episodes of the scenario's eval seed + 1000003, never those `squawk eval`\n"
       "uses by default. A progress bar with ETA goes to the terminal.\n\n"
       "  --estimator E   vpg: the paper's Eq. 5 (log-prob times the step reward);\n"
       "                  improved: reward-to-go, learned value baseline,\n"
       "                  normalised advantages and an entropy bonus\n"
       "  --resume        continue from DIR/checkpoint.ckpt (same seed and --episodes,\n"
       "                  which the step-size schedule spans): the run goes on\n"
       "                  exactly as if it had not stopped\n"
       "  --policy gpt2   fine-tune the GPT-2 prompt policy instead: --model tiny|DIR,\n"
       "                  --blocks K (trainable last blocks; default 2 for tiny, 1 for\n"
       "                  a folder), --head action|lm, --prompt FILE (default\n"
       "                  prompts/observation.lua), --episodes-per-update M; the\n"
       "                  checkpoint is written after every update\n",
       cmd_train},
      {"eval", "eval SCENARIO.lua --policy P   success rate and reward over evaluation episodes",
       "usage: squawk eval SCENARIO.lua [--policy random|zero|mvp|mlp] [--checkpoint FILE]\n"
       "                   [--episodes N] [--seed N] [--greedy] [--json] [--record FILE.jsonl]\n\n"
       "Runs the scenario's evaluation episodes (default 1000, numbered from the\n"
       "seed) with one policy and prints Table 3's columns: success rate, mean\n"
       "episode reward and its standard deviation.\n\n"
       "  --policy random  an untrained MLP, initialised from the seed\n"
       "  --policy zero    never turn\n"
       "  --policy mvp     BlueSky's MVP resolution steering the ownship (a classical\n"
       "                   reference, heading only)\n"
       "  --policy mlp     a trained MLP: --checkpoint FILE, by default the checkpoint\n"
       "                   shipped in models/\n"
       "  --policy gpt2    the GPT-2 prompt policy: --checkpoint FILE (default the\n"
       "                   fine-tuned tiny policy in models/), or --model tiny|DIR\n"
       "                   for an untrained head; --prompt FILE, --head action|lm\n"
       "  --greedy         take the most likely action instead of sampling\n"
       "  --json           print {success_rate, mean_reward, std_reward, episodes}\n"
       "  --record FILE    write every episode as JSON lines (squawk render reads it)\n",
       cmd_eval},
      {"table3", "table3 SCENARIO.lua   the paper's Table 3: untrained/trained MLP and GPT-2",
       "usage: squawk table3 SCENARIO.lua [--episodes N] [--seed N] [--mlp-checkpoint FILE]\n"
       "                     [--gpt2-checkpoint FILE] [--model tiny|DIR] [--csv FILE]\n\n"
       "Evaluates the four agents of the paper's Table 3 on the same evaluation\n"
       "episodes (default 1000) with one fixed seed (default the scenario's eval\n"
       "seed): an untrained MLP (initialised from the seed), an untrained GPT-2\n"
       "policy (the fine-tuned one's base model with a fresh action head, or\n"
       "--model), the trained MLP and the fine-tuned GPT-2 (checkpoints shipped in\n"
       "models/ unless given). Prints a markdown table, then CSV (or writes the CSV\n"
       "to --csv FILE).\n",
       cmd_table3},
  };
  return table;
}

}  // namespace squawk::app
