-- Prompt templates of the translation graph (scripts/translate/), loaded with
-- squawk.load_config("prompts/translator.lua"). Edit freely; no rebuild.
--
-- The first three are the paper's Appendix prompts (NL-to-API Command
-- Translator), with its Python f-string fields turned into placeholders.
-- Placeholders are written ${name} and replaced literally (no escaping), so
-- the braces of \boxed{...} stay as they are:
--   ${request}  the user's request, as typed
--   ${content}  the retrieved command documents (top K), one block each
--   ${context}  the retrieved documents again, for the verifier and filler
--   ${cmd}      the command the selector chose, e.g. ALT
--   ${usage}    that command's usage line from the registry
--   ${state}    the aircraft in the simulation, one line each (may be empty)
--   ${error}    the simulator's error message for the previous attempt
--   ${previous} the previous attempt that failed
-- A template may use any subset. Replies are read from the last \boxed{...};
-- the verifier's reply from its first YES or NO.

local M = {}

-- Command Verifier: does the request hold every required value? (YES / NO)
M.verifier = "Determine if the user gave you all the information you need to "
  .. "implement [${cmd}] as per the following rules, examples: ${context} \n\n"
  .. "in the following user request: ${request}. \n\n "
  .. "YES if you have ALL the required parameters to implement it, "
  .. "and NO if you're missing even a single value, like if the user did not "
  .. "provide a custom acid/speed or some other required parameter. "
  .. "Your response should be one word, either YES or NO. "

-- API Command Selector: pick one command name from the retrieved list.
M.selector = "${content} \n\n "
  .. "The user wants to implement a command from the above list of commands"
  .. " to do the following operation: \n ${request}. \n\n "
  .. "Select one command from the list of commands given "
  .. "and return it as \\boxed{command} "
  .. "that the user should use to implement what they outlined. "
  .. "For example, if the user wants to add an aircraft then you should"
  .. " return \\boxed{CRE} which is the command to create a new aircraft."

-- Command Parameter Selector/Validator: one complete instance of the command.
M.parameters = "${context} \n\n "
  .. "The user wants to implement the command ${cmd} as per the given usage criterion"
  .. " to do the following operation: \n ${request}. \n\n "
  .. "Follow the syntax provided to output a valid instance of the command as \\boxed{"
  .. "usage of command}"
  .. "You have to produce an instance of the command, complete with all filled in values"
  .. " that may be required according to the specification given."

-- squawk's additions (not in the paper) ---------------------------------------

-- Single-agent mode (Table 2 baseline): one call from request to command.
M.single = "${content} \n\n "
  .. "Aircraft in the simulation:\n${state}\n\n"
  .. "Translate the following request into BlueSky TrafScript using only the commands "
  .. "documented above: \n ${request}. \n\n "
  .. "Return the command line as \\boxed{command line}; separate several commands with ' ; '. "
  .. "If the request lacks a value that a command requires, return \\boxed{ASK} followed by "
  .. "the question to put to the user."

-- Appended to the parameter (or single) prompt after a failed attempt: the
-- simulator's own error, so the model can correct itself.
M.feedback = "\n\nYour previous answer was: ${previous}\n"
  .. "The simulator rejected it with this error: ${error}\n"
  .. "Correct the command and answer again in the same format."

-- Prefixed to the parameter prompt so callsigns and current values are known.
M.state = "Aircraft in the simulation:\n${state}\n\n"

-- The question put to the user when the verifier says NO.
-- Appended to the parameter and single prompts: the offline grammar's own
-- reading of the request, as context (it may be wrong or a question).
M.grammar = "\n\nAn offline grammar read this request as: ${reading}\n"
  .. "When the server constrains your reply to JSON, put each command as {\"name\", \"args\"} in "
  .. "\"commands\" and leave \"ask\" empty, or ask a question in \"ask\".\n"

M.ask = "I need more information to issue ${cmd} (usage: ${usage}). "
  .. "Which values should I use?"

return M
