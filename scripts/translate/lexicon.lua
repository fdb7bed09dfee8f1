-- The words of the offline grammar, as data: each entry is a list of
-- lower-case words (the lexer lower-cases and fixes spelling first). The
-- rules (translate/rules.lua) and the grammar's handlers
-- (translate/handlers.lua) name these lists instead of spelling words out,
-- so a new word for an existing idea is one edit here.
--
-- Numbers, units, callsigns, telephony designators, aircraft types and
-- latitude/longitude forms are read by the C++ extractors
-- (squawk.translate.utterance); this file holds the words that decide what
-- an instruction means.
return {
  -- words that carry meaning in an instruction (never read as names or fillers)
  keywords = { "climb", "descend", "descent", "maintain", "altitude", "level", "flight", "heading", "turn",
      "left", "right", "speed", "knots", "reduce", "increase", "decrease", "delete", "remove", "waypoint",
      "waypoints", "direct", "directly", "proceed", "create", "aircraft", "destination", "origin", "vertical",
      "rate", "pause", "resume", "continue", "simulation", "sim", "scenario", "trail", "trails", "turbulence", "noise",
      "conflict", "conflicts", "detection", "resolution", "resolve", "separation", "minimum", "minima", "radius",
      "bank", "angle", "callsign", "degrees", "north", "south", "east", "west", "feet", "thousand", "hundred",
      "expedite", "cleared", "define", "route", "position", "reposition", "teleport", "move", "spawn",
      "generate", "place", "lateral", "navigation", "enable", "disable", "switch", "heavy", "mach", "seconds",
      "minutes", "minute", "second", "hours", "speedbird", "lufthansa", "descending", "climbing", "faster",
      "slower", "slow", "fast", "forward", "skip", "ahead", "timestep", "step", "seed", "random", "reset",
      "print", "echo", "load", "open", "freeze", "hold", "protected", "zone", "height", "look", "lookahead",
      "method", "potential", "voltage", "modified", "append", "insert", "add", "show", "hide", "list", "where",
      "details", "status", "lower", "raise", "cruise", "point", "fly", "towards", "around", "opposite",
      "direction", "same", "match", "double", "present", "current", "vectors", "vector", "traffic", "approach",
      "departure", "contact", "radar", "correction", "negative", "immediately", "until", "advised", "then",
      "when", "once", "reaches", "passes", "through", "below", "above", "fpm", "knot", "airspeed", "sink",
      "plan", "departed", "shift", "activate", "chuck", "deactivate", "unpause", "start", "over", "real", "time", "half",
      "nautical", "miles", "percent", "degree", "latitude", "longitude", "named", "called", "type", "niner",
      "expect", "localizer", "final", "sequence", "spacing", "decimal", "brake", "limit", "custom", "fix",
      "visual", "runway", "cross", "altimeter", "maintained", "desc", "clb", "rpz", "hpz",
      -- a position's labels as typed ("lat 51.95 lon 4.35"), and the random number generator a seed seeds
      "lat", "lon", "lng", "rng", "prng",
      -- a flight level as typed ("descend FL120, Finnair 7": never a garbled callsign's word)
      "fl",
      -- the wind a request sets ("wind from 270 at 40 kt"): never part of a spoken callsign
      "wind", "winds",
      -- the verb of a setting ("set wind two five zero at three zero", "set heading two five zero"): with the
      -- instruction word after it, never a garbled callsign's words
      "set",
      -- a game programmer's words for commands ("despawn", "rotate 90 clockwise", "timescale 4"; not "tp",
      -- the letters of callsigns: "Easy 81TP")
      "despawn", "warp", "destroy", "rotate", "yaw", "clockwise", "counterclockwise",
      "anticlockwise", "hitbox", "timescale", "tick", "banking", "respawn",
      -- ("make five more A320s": a creation's verb, never a garbled callsign's word)
      "make", },
  -- registry command names that are everyday English words ("a delay", "the line"): said in a
  -- sentence they name no command; any other registry name said ("rmethv") names its command
  english_command_names = { "after", "area", "at", "bank", "before", "box", "call", "circle", "delay", "help",
      "hold", "line", "lines", "noise", "run", "start", "wind", "trail", "trails", "load", "open", "continue",
      "polygon", "reset", "seed", "echo", "perf" },
  -- words that carry none ("please", "uh"): skipped before a callsign or condition
  -- (the particles of Singapore and Malaysian English: "ok lah", "can lah", "like that lor"; and of Filipino
  -- said in English, each a filler above in another tongue: "po" (respect, as "please"), "sige" (all right),
  -- "ano" (um), "yung" (the), "na" (now): "resume na po"; and of Nigerian and Ghanaian Pidgin: "abeg" (please),
  -- "oya" (come on, now): "abeg check Speedbird 75 for me", "oya show me Arik 104")
  fillers = { "ah", "uh", "um", "er", "eh", "euh", "oh", "the", "a", "an", "please", "pls", "okay", "ok", "yeah", "so",
      "and", "now", "lah", "leh", "lor", "po", "sige", "ano", "yung", "na", "abeg", "oya",
      -- (Singlish "anot", "or not", closing a question: "can pause the sim anot?")
      "anot",
      -- (Japanese hesitations: "eto", "etto", "eeto", as "uh")
      "eto", "etto", "eeto", },
  -- Every word accounted for (docs/translator_trust.md): a request becomes commands only when each of its
  -- words is part of a callsign, place, type or value the parse read, an instruction word (the rules' words
  -- and this file's lists), or a word of one of these classes; any other word is a leftover, asked about by
  -- name. Classes of English, never a request's words: a new word joins the class it belongs to.
  accounted = {
    -- closed-class English, which carries no instruction of its own
    articles = { "a", "an", "the", "this", "that", "these", "those", "some", "any", "each", "every", "all", "both",
        "either", "neither", "another", "other", "others", "such", "what", "which", "whose", "much", "many",
        "more", "most", "few", "less", "least", "several", "enough", "own", "same", "whole", "entire", "complete", "further",
        "whatever" },
    pronouns = { "i", "me", "my", "mine", "myself", "you", "your", "yours", "yourself", "we", "us", "our", "ours",
        "ourselves", "he", "him", "his", "himself", "she", "her", "hers", "herself", "it", "its", "itself",
        "they", "them", "their", "theirs", "themselves", "one", "ones", "someone", "somebody", "anyone",
        "anybody", "everyone", "everybody", "something", "anything", "everything", "nothing", "nobody", "who",
        "things", "stuff", "else",
        "whom", "there",
        "here", "i'm", "i'd", "i'll", "i've", "you're", "you'd", "you'll", "you've", "we're", "we'd", "we'll",
        "we've",
        -- Caribbean English's "you" and "you're" ("Caribbean 417 yuh cleared direct POS")
        "yuh", "he's", "she's", "it's", "it'll", "they're", "they'd", "they'll", "they've", "that's",
        "there's", "here's", "what's", "let's", "who's", "where's", "how's", "that'll" },
    auxiliaries = { "be", "am", "is", "are", "was", "were", "been", "being", "have", "has", "had", "having", "do",
        "does", "did", "doing", "done", "get", "gets", "got", "getting", "go", "goes", "going", "gonna",
        -- (Nigerian Pidgin's "be": "where Arik 300 dey", "the two dey for conflict")
        "dey" },
    modals = { "can", "could", "may", "might", "must", "shall", "should", "will", "would", "ought", "need",
        "needs", "wanna",
        -- (an obligation a report states: "X is required to cross CNR at FL120")
        "required", "obliged" },
    prepositions = { "about", "above", "across", "against", "along", "among", "around", "as", "at", "behind",
        "below", "beneath", "beside", "between", "beyond", "by", "down", "during", "for", "from", "in", "inside",
        "into", "like", "near", "of", "off", "on", "onto", "out", "outside", "over", "past", "per", "than",
        "through", "to", "toward", "towards", "under", "up", "upon", "via", "with", "within", "round", "onto" },
    conjunctions = { "and", "but", "or", "nor", "so", "yet", "also", "because", "that", "though", "although",
        "whether", "while", "where", "how", "why", "then", "plus" },
    -- discourse markers and degree adverbs
    discourse = { "well", "right", "alright", "just", "also", "too", "very", "really", "quite", "rather", "bit", "lot",
        "little", "only", "even", "still", "already", "again", "actually", "maybe", "perhaps", "probably",
        "now", "first", "next", "last", "soon", "quickly", "slightly", "fine", "good", "great", "sure",
        -- (urgency of the whole request, "kindly do the needful urgently": what squawk sends runs at once)
        "urgently",
        -- (how hard a turn is flown, which squawk's turn model does not take: "hard left heading 350", named in the
        -- note when said as the manner, not_simulated)
        "hard", "sharp", "sharply", "aggressive", "aggressively",
        -- (a military controller's "snap", at once: "snap right heading 010", "snap left 45 degrees")
        "snap",
        -- (spoken hedges: "the clock is running kinda slow, go 2x")
        "kinda", "sorta", "somewhat",
        -- (a chatty speaker's degree: "it's turning super aggressively")
        "super",
        "ok", "okay", "oh", "hmm", "hm", "ehm", "erm", "uhm", "hey", "yes", "yeah", "sorry", "anyway", "righto", "exactly", "possibly", "currently",
        "precisely", "roughly", "approximately",
        -- (interjections of a chatty speaker: "Ooh, and add Rosun ...", "ah, and the Speedbird ...")
        "ooh", "ah", "ahh", "aah",
        -- (and a Singaporean's or Hong Konger's dismay, "aiyah, disregard, maintain FL300")
        "aiyah", "aiya", "aiyoh", "aiyo",
        -- (and a Dutch speaker's "let me see", "even kijken, turn right 20 degrees"; a Swiss speaker's tag, "gell")
        "kijken", "gell",
        -- (and a Turkish speaker's "okay?", "tamam"; a Belgian speaker's "come on", "allez")
        "tamam", "allez",
        -- (a value said loosely, "250-ish", "like 250ish": the value said is the one flown, as "roughly 250")
        "ish", "afterwards", "afterward", "meanwhile", "completely", "fully",
        -- (a report's order of events and degree: "was subsequently given", "disable it altogether"; a first level
        -- cleared, "climb 6000 feet initially")
        "subsequently", "thereafter", "altogether", "initially", "instantly",
        "entirely", "moment", "away", "back", "aside", "apart", "nearer", "farther",
        -- the same markers in Spanish and Portuguese, said in English by their speakers ("vamos, LATAM 3402 ...",
        -- "bueno, ...", "entonces ...", "bom, ...", "olha: ...")
        "vamos", "bueno", "entonces", "listo", "dale", "vale", "venga", "mira", "ojo", "bom", "entao", "então", "olha",
        "pronto", "beleza",
        -- comparatives of a remark on the set-up ("a bit nicer", "closer to 90", "a shorter look-ahead")
        "nicer", "better", "closer", "shorter", "longer", "smaller", "larger", "bigger",
        -- (a remark on the traffic given as the reason: "it and EDV5102 are gonna be way too close")
        "close",
        -- (a size asked about: "how large is the protected zone radius?")
        "large", "big",
        -- a demonstration's remarks to its audience ("make it snappy", "for realism", "here's the fun part")
        "snappy", "realism", "realistic", "fun",
        -- (a British speaker's understated degree on the whole request: "would you mind awfully having ...",
        -- "would you mind terribly deleting ...")
        "awfully", "terribly",
        -- an Irish or British speaker's warm acknowledgement before or between instructions ("grand, now the
        -- Ryanair ...", "ok lovely, the Delta can start down", "sound, the Emerald can have 250 knots")
        "grand", "lovely", "sound",
        -- an Australian speaker's acknowledgement and degree ("no worries, the Saab can go", "heaps of traffic ahead",
        -- "speed it up heaps, like times ten": "heaps" is "a lot", the value said with it is the one meant)
        "no worries", "no dramas", "heaps",
        -- (and a New Zealander's: "delete Jetstar 235, sweet as", "turn left heading 180, good as gold")
        "sweet as", "good as gold" },
    -- courtesy and framing of a request
    courtesy = { "please", "kindly", "thanks", "thank", "cheers", "like", "want", "wants", "wish", "let", "lets",
        "mind", "able", "possible", "chance", "ask", "tell", "make", "have", "try", "see", "help", "give",
        "put", "throw", "keep", "set", "bring", "take", "ready", "appreciate", "instruct", "sure",
        -- (the formal passive of "bring": "it may be brought down to FL110", "the Akasa may be brought to 250 knots")
        "brought",
        -- an aircraft handed to a teammate to deal with ("can you take Ayline 672 and sort its speed out")
        "sort",
        -- verbs of opinion that frame a request ("I think the easyJet should go direct")
        "think", "guess", "believe", "suppose", "reckon", "wonder", "hope", "prefer", "realise", "realize",
        "know", "remember", "forget", "forgot", "notice", "grateful", "thankful",
        -- verbs of the speaker's own talk ("while I explain this")
        "explain", "brief", "talk", "discuss", "speak",
        -- an experimenter watching what a run does ("let's watch it", "see the effect")
        "watch", "observe", "effect", "effects", "result", "results", "outcome", "happens", "happen", "happening",
        "happened",
        -- the study a run belongs to, told as its story ("it departed there in our story", "for my study")
        "story", "study", "storyline", "narrative",
        -- a newcomer excusing or naming their words ("I apologise for my ignorance of the terminology, but ...", "I
        -- believe the term is vertical navigation")
        "ignorance", "terminology", "term", "jargon", "apologise", "apologize", "apologies",
        -- an experiment's trials and its framing of what the simulation plays ("we pretend that ...", "could you
        -- arrange for the simulation to pause ...", "simply keep flying straight")
        "trials", "pretend", "imagine", "arrange", "simply",
        -- (a participant's consent, the reason a run starts: "she's here and consented, start it back up")
        "consent", "consented", "consents",
        -- what the speaker thanks for, said with no article by a non-native speaker ("thank you for cooperation")
        "cooperation", "cooperating", "patience" },
    -- the people in the room, addressed ("ok observers, I'm going to start the clock", "ok folks, first one")
    audience = { "folks", "guys", "observers", "observer", "team", "gentlemen", "ladies", "y'all", "everybody",
        -- the same in Spanish and Portuguese, where instructors teach in English ("chicos, look:", "ok pessoal")
        "chicos", "chicas", "muchachos", "alumnos", "estudiantes", "amigos", "pessoal", "galera", "alunos",
        "turma",
        -- a person addressed with respect, as Indian controllers do ("sir where is IFLY 2171 showing"; Hindi "ji"
        -- closing a request, "pause the simulation ji")
        "sir", "madam", "ma'am", "ji",
        -- a friend addressed in chat ("how fast are you going mate", typed "m8")
        "mate" },
    -- chat shorthand and interjections of typed notes ("what's ryanair doing rn", "lol", "ugh", "thx")
    chat = { "rn", "atm", "asap", "lol", "lmao", "ugh", "argh", "meh", "oops", "tbh", "imo", "btw", "fyi", "plz",
        "thx", "pls", "haha", "idk", "tho", "tbf", "yo", "omg", "bruh", "dude", "ngl", "smh", "thnx", "thanx", "tysm",
        -- the Irish call for attention, "come here" ("United two tree, c'mere, what level are you at")
        "c'mere", "cmere",
        -- a fault of the simulation given as the reason ("kill aza204 its bugged"), a break taken ("need coffee")
        "bugged", "buggy", "glitched", "glitchy",
        -- (an aircraft created twice, given as the reason to delete it: "delete gulf air 215, its a duplicate")
        "duplicate", "duplicated", "dupe",
        -- a programmer's look inside the simulation ("debug info on WJA661": its state shown)
        "debug", "debugging", "coffee", "lunch", "brb",
        -- a telephone call taken, the reason for a pause or a break in the request ("pause the sim, phone",
        -- "sorry phone - ...")
        "phone",
        -- a pilot of an online network gone, given as the reason for removing the aircraft ("dc'd", "he's
        -- disconnected", "went afk", "timed out"; "pilot" with them: courtesy_phrases)
        "dc'd", "dcd", "dced", "disconnected", "disconnect", "disconnects", "afk", "offline", "logged", "timed",
        "went", "gone", "network", "vatsim", "ivao",
        -- an airspace infringed, given as the reason ("delete N512RK he busted the bravo")
        "busted", "infringed",
        -- the online networks' text-speak: thanks and goodbyes typed short ("ty", "kthx", "kthxbye"), a laugh typed
        -- as a face ("xD"), and a fault of the client given as the reason ("despawn X its lagging", "its stuck")
        "ty", "tyvm", "thnx", "thanx", "kthx", "kthxbye", "cya", "xd", "lag", "lagging", "laggy", "stuck",
        -- British thanks typed short ("RYR82LK fl330 pls ta")
        "ta" },
    -- radiotelephony courtesy
    radiotelephony = { "good", "day", "morning", "afternoon", "evening", "hello", "hi", "roger", "wilco", "copy",
        "copied", "affirm", "affirmative", "understood", "g'day", "bye",
        -- an Irish greeting ("Delta forty four, howya, proceed direct ENIRI")
        "howya", "howaya",
        -- a request granted, a report acknowledged ("Mach .84 approved", "position report received")
        "approved", "received",
        -- the pilot asked to acknowledge the instruction just given ("turn left heading 060, acknowledge")
        "acknowledge",
        -- an airspeed said as indicated ("fly 250 knots indicated", "320 knots IAS": squawk's speeds are
        -- calibrated, the same)
        "indicated", "ias", "cas",
        -- a clearance given again in place of the one before ("recleared direct CAPER", "re-cleared FL250")
        "recleared", "reclear",
        -- a readback the controller corrects ("readback incorrect, I said FL350, not 340")
        "readback", "read-back", "incorrect", "said",
        -- radar identification stated to the pilot ("Budapest Radar, identified, descend FL130")
        "identified", "identification",
        -- the same courtesy in Spanish or Portuguese ("descend FL120, gracias", "momentito, por favor", "muchas
        -- gracias", "muito obrigado")
        "gracias", "obrigado", "obrigada", "por", "favor", "momentito", "buenos", "buenas", "dias", "días",
        "muchas", "muchisimas", "muchísimas", "muito",
        "tardes", "noches",
        -- and in Dutch ("KLM 1234, goeiemorgen, descend ...")
        "goeiemorgen", "goedemorgen", "goedemiddag", "goedenavond", "goeienavond",
        -- and in French ("climb FL120, bonjour", "merci, au revoir")
        "bonjour", "bonsoir", "merci", "salut", "revoir",
        -- (and the Swiss French greeting and leave-taking, "adieu, ...")
        "adieu",
        -- greetings of Australia, New Zealand and South Africa ("G'day mate", "kia ora", "howzit")
        "mate", "kia", "ora", "howzit",
        -- thanks in Fijian, Tongan, Samoan and Solomon Islands Pijin ("vinaka", "malo", "fa'afetai", "tanggio",
        -- "tenkyu")
        "vinaka", "malo", "fa'afetai", "faafetai", "tanggio", "tenkyu",
        -- the same courtesy in German ("Grüß Gott", "danke", "bitte", "servus"; "Entschuldigung" is
        -- lexicon.discourse_words' sorry)
        "gruss", "gott", "servus", "hallo", "danke", "bitte", "guten", "gruezi",
        -- the same in the Nordic and Baltic languages ("Hej, ...", "Tack", "Kiitos", "Labdien", "Paldies")
        "hej", "hei", "moi", "tere", "tack", "takk", "tak", "kiitos", "labdien", "paldies", "labas", "aciu",
        "aitah", "sveiki",
        -- the same in the Central European languages ("dobrý den", "dzień dobry", "szia", "dobar dan", "děkuji")
        "dobry", "dobre", "dobar", "dober", "dzien", "szia", "sziasztok", "szervusz", "czesc", "ahoj", "dekuji",
        "dakujem", "dziekuje", "dziekujemy", "koszonom", "hvala", "nashledanou", "prosim",
        -- the greetings, thanks, farewells and "please" of the world's controllers, said in their own language
        -- in an English clearance ("descend FL180, grazie", "Aegean 412, kalimera, ..."; the words of two or
        -- more are courtesy_phrases). A fix, airport or aircraft of the scene by the same name is read as
        -- that name first (G:unknown_names asks), never set aside. Italian:
        "grazie", "prego", "buongiorno", "buonasera", "buonanotte", "arrivederci", "arrivederla", "ciao", "salve",
        "favore", "andiamo", "perfetto", "benissimo",
        -- (a word calling for attention before the instruction: "Alpine 4521, attenzione, turn right immediately")
        "attenzione", "achtung", "atencion", "atención",
        -- Spanish and Portuguese (beyond those above)
        "hola", "saludos", "chao", "tchau", "porfa", "valeu", "obrigadao", "ola",
        -- French, German and Dutch (beyond those above)
        -- ("ok voilà, continue the simulation": there, that is it)
        "voila", "voilà",
        "svp", "tschuss", "tschues", "wiedersehen", "wiederhoren", "moin", "bedankt", "dankjewel", "dankuwel",
        "alstublieft", "alsjeblieft", "goedemorgen", "goedemiddag", "goedenavond", "goedendag", "doei", "hoi",
        -- the Nordic languages (beyond those above)
        "tusind", "tusen", "hejsan", "hejda", "huomenta", "paivaa", "moro", "godmorgen", "godmorgon",
        -- Greek, transliterated
        "kalimera", "kalispera", "kalinychta", "kalinihta", "efcharisto", "efharisto", "efxaristo", "parakalo",
        "yassou", "yiasou", "geia", "antio", "taxidi",
        -- Turkish
        "merhaba", "gunaydin", "tesekkurler", "tesekkur", "tesekkurlar", "lutfen", "hoscakal", "hosca",
        -- Polish and Czech (beyond those above)
        "prosze", "dobranoc", "dekujeme", "diky", "dzieki",
        -- Russian, transliterated
        "spasibo", "pozhaluista", "pozhaluysta", "pozhalujsta", "zdravstvuyte", "zdravstvuite", "privet",
        "svidaniya", "dobroye", "dobryy", "dobrogo",
        -- (and the thanks of Uzbek and Kazakh controllers, "rahmat", "rakhmet")
        "rahmat", "raxmat", "rakhmat", "rakhmet",
        -- Arabic, Hebrew and Hindi, transliterated
        "shukran", "marhaba", "salam", "salaam", "assalamu", "alaikum", "alaykum", "ahlan", "afwan", "yalla",
        "inshallah", "inshaallah", "inchallah", "inchaallah", "inshalla", "inchalla", "bismillah", "alhamdulillah", "jazakallah", "barakallah", "shalom", "toda", "namaste", "namaskar", "dhanyavad", "dhanyawad", "shukriya", "kripya",
        -- Japanese, Korean and Chinese, romanised
        "arigato", "arigatou", "konnichiwa", "ohayo", "ohayou", "gozaimasu", "onegaishimasu", "sayonara",
        "sumimasen", "kamsahamnida", "gamsahamnida", "annyeong", "annyeonghaseyo", "annyonghaseyo", "xiexie",
        "nihao", "zaijian",
        -- Thai, Malay, Indonesian and Filipino, romanised ("sawasdee khrap", "terima kasih", "salamat")
        "sawasdee", "sawatdee", "sawadee", "khrap", "krap", "khob", "khun", "terima", "kasih", "selamat", "pagi",
        -- (the Thai speaker's polite particle closing a sentence: "krab" said by a man, "ka" or "kha" by a woman)
        "krab", "khrab", "ka", "kha", "kup", "khup",
        -- (the particles of Indonesian and Malay said in English, softening or closing a request: "climb FL300 ya",
        -- "pause dulu", "stop the sim sekejap" (for a moment), "turn left 20 dong"; "lah" is a filler)
        "ya", "dulu", "sekejap", "kejap", "dong", "deh", "sih", "nih",
        "salamat", "maraming",
        -- (the other particles of Filipino said in English (Taglish), beside the fillers "po", "sige", "ano",
        -- "yung" and "na": "opo" of respect, "iyong" (the), "muna" (first, for a while: "pause muna"), "lang"
        -- (just), "naman" (then, though), "ay" before an apology ("ay sorry"))
        "opo", "iyong", "muna", "lang", "naman", "ay",
        -- the languages of Africa, romanised: Swahili ("asante sana", "sawa", "pole pole": slowly, easy),
        -- Amharic ("ishi": OK), Nigerian and Ghanaian Pidgin ("chale": mate; "abeg" and "oya" are fillers),
        -- Hausa, Igbo, Yoruba, Twi, Zulu, Xhosa and Afrikaans
        "asante", "sana", "sawa", "karibu", "jambo", "habari", "tafadhali", "kwaheri", "pole", "mambo", "poa",
        "ishi", "amesegenalehu", "tenastelign", "selam", "chale", "chaley", "biko", "daalu", "nagode",
        "sannu", "medaase", "akwaaba", "sawubona", "ngiyabonga", "enkosi", "dankie", "asseblief", "yebo", "eish",
        -- and of the Gulf ("tamam": OK)
        "tamam", "habibi", "mashallah",
        -- (and the Turkish of Turkey and Cyprus beyond "tamam": "peki", all right; "tamamdır", done; "sağol", thanks;
        -- "efendim", sir)
        "peki", "tamamdir", "sagol", "sagolun", "efendim",
        -- the thanks, "please" and excuse-me of a research lab's other voices, romanised: Persian ("mersi",
        -- "mamnoon", "lotfan"), Thai ("khob khun krub"), Indonesian ("permisi", "tolong"), Italian, Spanish and
        -- Portuguese ("scusi", "disculpe", "desculpa", "com licenca"), German ("danke schön"), Polish ("przepraszam");
        -- Greek "signomi" is lexicon.discourse_words' sorry; the apologies of Persian, Indonesian and Korean ("bebakhshid", "maaf", "joesonghamnida")
        -- are lexicon.discourse_words' sorry, a correction's mark as English "sorry" is
        "mersi", "mamnoon", "mamnun", "motashakkeram", "lotfan", "krub", "khrub", "khop", "permisi", "tolong",
        "scusi", "scusa", "scusate", "disculpe", "disculpa", "perdone", "perdona", "desculpa", "desculpe", "licenca",
        "schon", "schoen", "przepraszam",
        -- (Malaysian and Singaporean typed thanks, "tq", "tqvm"; Indonesian "pak", sir, and "selamat siang", good
        -- afternoon, with "pagi", "sore" and "malam" its morning, late afternoon and evening)
        "tq", "tqvm", "pak", "bu", "selamat", "siang", "pagi", "sore", "malam" },
    -- phrases of courtesy that hold a word which means something elsewhere ("when", "if"):
    -- explained whole
    courtesy_phrases = { "pull up", "when you get a chance", "when you can", "when you're ready", "when ready",
        -- small talk on a quiet shift and its pace ("evening KLM12, nice and quiet tonight, descend ...", "... at your
        -- discretion, long way down tonight", "plenty of time", "pause it, phone's ringing"): no value, no instruction
        "nice and quiet tonight", "nice and quiet", "quiet one tonight", "a quiet one tonight", "quiet tonight",
        "quiet night", "long way down tonight", "plenty of time", "lots of time", "phone's ringing", "phone is ringing",
        "let's have a break", "have a break", "take a break", "till something happens", "until something happens",
        "short break", "quick break", "coffee break", "comfort break", "nothing interesting", "nothing happening",
        "nothing much happening", "questions answered",
        -- the blessings of Arabic-speaking (and other Muslim) controllers, said in English or transliterated,
        -- before, between or after the instructions ("God willing, climb FL370", "..., if you please, God bless
        -- you"): they ask for nothing. "God" said alone stays unknown.
        "god willing", "if god wills", "if god wills it", "god bless you", "god bless", "may god bless you",
        "god reward you", "may god reward you", "god keep you", "may god keep you", "god protect you",
        "may god protect you", "thank god", "thanks be to god", "praise be to god", "praise god", "by god's will",
        "with god's help", "incha allah", "insha allah", "in sha allah", "insh allah", "inshaa allah", "in shaa allah",
        "masha allah", "ma sha allah", "bism allah", "alhamdu lillah", "al hamdu lillah", "jazak allah",
        "jazak allahu khairan", "jazakallah khair", "barak allah", "barak allahu feek", "if you please",
        "when able", "if able", "if you can", "if you could", "if you would", "if possible",
        "if you don't mind", "if it's not too much trouble", "as soon as possible", "as soon as you can",
        -- (a retired controller's courtesy: "..., if you'd be so kind", "thank you ever so much", "be a dear and
        -- descend ...", "when you have a moment", "if I may")
        "if you'd be so kind", "if you would be so kind", "if you'd be kind enough", "if you would be kind enough",
        "if i may", "ever so much", "be a dear and", "when you have a moment", "when you've a moment",
        -- (a study's step named before the request: "ok, before the next trial, could you bring KLM1234 down ...")
        "before the next trial", "before the next run", "before the next session", "for the next trial",
        "for the next run", "between trials", "between runs", "before we start",
        -- (a radio check before the instruction: "Virgin 45F, are you there? climb FL340")
        "are you there", "you there", "how do you read", "do you read", "do you read me", "how do you read me",
        -- the listener's convenience and leave said whole ("..., please, when convenient", "if that's alright with you")
        "when convenient", "whenever convenient", "when it's convenient", "when it is convenient", "at your convenience",
        "if that's alright with you", "if that's all right with you", "if that's alright", "if that's all right",
        "if that is alright", "if that is all right", "if that's okay", "if that's ok",
        -- a polite speaker's hedges on the whole request ("..., if that is at all possible", "would it be too much
        -- trouble to ask ...", "if it's no trouble", "if that's a thing", "of course", "we don't need it after all")
        "if that is at all possible", "if at all possible", "if that is possible", "if that's possible",
        "if it is possible", "if it's possible", "if it's no trouble", "if it is no trouble", "if that's no trouble",
        "if that is no trouble", "would it be too much trouble", "is it too much trouble", "if that's a thing",
        "if that is a thing", "thanks a million", "thanks a mil", "if that works", "if that works for you", "if it works", "if it works for you",
        "of course", "after all", "i apologise",
        -- a formal speaker's leave asked of the listener (Persian "ba ejazeh", said in English: "With your
        -- permission, Aseman 3858 turn left ...", "..., with your kind permission"): it asks for nothing
        "with your permission", "with your kind permission", "with your good permission", "by your leave",
        -- (the system addressed as a person, as Indonesian and Malay speakers address the one they ask: "Mister system,
        -- Lion 721 ...")
        "mister system", "mr system", "mr. system",
        "if you permit", "if you permit me", "if you would permit me", "i apologize", "my apologies", "as a separate thing", "block of trials",
        "blocks of trials",
        -- a researcher's aside on their own frankness ("I'm honestly not sure", "Honestly, ...")
        "honestly",
        "if the computer can cope with it", "if the computer can cope", "if the simulation can cope with it",
        -- urgency ("descend FL200 at once", "right away": what squawk sends runs at once)
        -- (the speaker's opinion, in a report: "..., which is what the controller ought to have done, in my view")
        "in my view", "in my opinion", "in our view", "in our opinion", "to my mind",
        "at once", "right away", "straight away", "without further delay",
        -- (instructions to several aircraft said to run together: "AFR12 turn left 30, DLH10 turn right 30,
        -- simultaneously": what squawk sends in one request runs at the same time)
        "simultaneously", "at the same time",
        -- the aircraft's (or the simulation's) ability, as "if able" ("up to 390 if the sim lets him")
        "if he can", "if she can", "if it can", "if he's able", "if she's able", "if it's able", "if the sim lets him",
        "if the sim lets her", "if the sim lets it", "if the sim allows", "if the sim allows it", "if the sim can",
        "if performance allows", "if performance permits",
        "at the moment", "for a moment", "for now", "right now", "for the moment", "in order to", "in that order",
        "in this order", "sorry to bother you", "to be safe", "to be sure", "to be on the safe side", "just in case",
        "after that", "after this",
        -- Indian English office courtesy closing a request ("..., kindly do the needful", "please revert once done":
        -- do what was asked, reply when done); squawk's commands run as sent and answer nothing back
        "do the needful", "revert once done", "revert when done", "revert after doing", "revert back",
        -- a message said again, in Indian English as "I say again" is elsewhere ("Express India 1356, once again,
        -- descend 9000 feet"): never a condition
        "once again",
        -- (the same in Singapore and Malaysian English, "Batik 7151, one more time, descend FL110"; and the check a
        -- clearance closes with there, "..., reduce speed 230, confirm or not": read it back)
        "one more time", "confirm or not",
        -- (and in Vietnamese and Thai English the polite question a request is put as, before or after it: "turn
        -- left heading 180, can or not?", "can or not, Nok Air 116 speed 280?": do it)
        "can or not", "can or cannot", "can or can not",
        -- a part of the airspace a study is run in, in two words ("the high altitude en route block", as "en-route")
        "en route",
        -- an aircraft handed to a teammate ("can you look after Logan 52B for me - ...")
        "look after",
        -- a demonstration's pointers to the audience ("watch the data block", "here's the fun part")
        "data block", "data blocks", "data tag", "the fun part",
        -- (a stretch of the run skipped by fast time: "we would like to skip the quiet part; fast-forward ...")
        "the quiet part", "the boring part", "the slow part", "the quiet period", "the boring bit", "the quiet bit", "dobry den", "dobar dan", "dober dan", "jo napot", "na shledanou",
        "do widzenia", "do videnia", "kalo taxidi", "kali mera", "kali spera", "buona giornata", "buona serata",
        "buon viaggio", "grazie mille", "per favore", "bon voyage", "bonne journee", "bonne soiree", "boa tarde",
        "boa noite", "boa viagem", "bom dia", "buen viaje", "hasta luego", "guten tag", "god dag", "god morgen",
        "ha det",
        -- (the Nordic languages' thanks and farewells in two or more words: "tack så mycket", "mange tak", "hej då")
        "tack sa mycket", "tack tack", "tusen tack", "mange tak", "tusind tak", "takk skal du ha", "tak skal du have",
        "hej da", "hej hej", "ha det bra", "vi ses", "god morgon", "god kvall", "god kveld", "god aften", "dank je", "dank u", "iyi gunler", "iyi ucuslar", "iyi aksamlar", "iyi geceler", "iyi calismalar",
        "iyi yolculuklar", "iyi nobetler", "kolay gelsin", "gule gule", "sag ol", "sag olun", "hosca kalin",
        "tesekkur ederim", "tesekkur ederiz", "cok tesekkurler", "cok tesekkur ederim",
        -- (Croatian and Slovenian thanks in two words: "hvala lijepa", "puno hvala", "najlepša hvala")
        "hvala lijepa", "hvala lepa", "puno hvala", "hvala puno", "hvala vam", "najlepsa hvala", "lijepa hvala", "do svidaniya", "ni hao", "ma'a salama",
        "ma salama", "maa salama", "maa salaama", "m goi", "mh goi", "doh je", "dor je", "no wahala",
        "at pilot's discretion", "at your discretion",
        "pilot's discretion",
        "pilot discretion", "your discretion", "at pilot discretion", "pilots discretion", "at pilots discretion",
        -- a place asked about beside another ("where is DILUM in relation to the aircraft")
        "in relation to", "with respect to", "with regard to",
        -- help offered with a value given twice ("... -- that's 50.7 / 16.2 in decimal if it helps")
        "if it helps", "if that helps", "in case it helps", "in case that helps",
        -- the pilot of an online network gone, the reason for removing the aircraft ("pilot dc'd")
        "pilot dc'd", "pilot dcd", "pilot dced", "pilot disconnected", "pilot went afk", "pilot is afk", "pilot afk",
        "pilot timed out", "pilot logged off", "pilot is gone", "pilot gone", "pilot left", "pilot has left",
        "pilot has disconnected", "connection lost", "lost connection", "lost his connection", "lost her connection",
        -- (and in Nigerian Pidgin, "delete Danaco 361, e don land": it has landed, or left)
        "e don land", "e don comot", "e don go",
        -- the rest of a route kept after a direct-to ("dct BIG, rest of route unchanged")
        "rest of route unchanged", "rest of the route unchanged", "rest of route as filed",
        -- a place said as over a point ("move it right on top of DUDSO")
        "right on top of", "on top of",
        -- the speaker holding the room a moment ("hang on, freeze it there")
        "hang on", "bear with me", "stand by",
        -- a British speaker's understatement of a change whose value is said ("turn right a touch, heading 020",
        -- "come down a touch, say FL120"): the value said is the one flown, as "a bit"
        "a touch", "just a touch",
        -- the pace of a request left to the aircraft ("when it's ready, no rush", "in its own time"): what squawk
        -- sends runs at once
        "when it's ready", "when it is ready", "when it's able", "when it is able", "no rush", "no hurry",
        "there's no rush", "there's no hurry", "in its own time", "in their own time",
        -- (the same said as no trouble to the speaker, "heading 090, no bother", Scots "nae bother")
        "no bother", "no bother at all",
        -- the speaker's own side ready again, Scots and northern English ("ok that's us, set it going again")
        "that's us", "that's us ready", "that's us done",
        -- the speaker's own stop of a fast-forward said in a clause of its own ("fast-forward, and I'll say when
        -- to stop"): fast time with no end
        "i'll say when to stop", "i will say when to stop", "i'll tell you when to stop",
        "i will tell you when to stop",
        -- the reason an aircraft is removed ("remove it please, it's just clutter")
        "it's just clutter", "it is just clutter", "it's clutter", "just clutter",
        -- (an aircraft whose part in the exercise is over: "take the Jet2 off, it's finished")
        "it's finished", "it is finished", "it's done with", "it's finished with",
        -- a British speaker's apology or hedge opening a request ("sorry to be a pain, but ...", "would it be
        -- terribly inconvenient to ...")
        "sorry to be a pain", "sorry to be a nuisance", "would it be inconvenient", "would it be terribly inconvenient",
        "would it be awfully inconvenient", "would it be too inconvenient",
        -- the simulation's conflict resolution named by a pilot's word for it ("resolution advisories on, MVP")
        "resolution advisories", "resolution advisory",
        -- urgency, said with a negation ("descend FL150 without delay")
        "without delay", "with no delay", "without any delay",
        -- an instruction put as the controller's proposal, as French "je vous propose" ("I propose you to turn
        -- left heading 100", "I propose you a direct to MOPAR"), and the check it closes with ("..., it's ok for
        -- you?"): the instruction given; said of someone else ("the pilot proposes ...") it stays asked
        "i propose you", "we propose you", "i suggest you", "we suggest you", "i recommend you", "we recommend you",
        "is it ok for you", "it's ok for you", "is that ok for you", "is it okay for you", "it's okay for you",
        "is that okay for you",
        -- a Japanese speaker's hedges on the whole request, and apologies and asides around it ("If there is no
        -- problem, please.", "..., if this is possible", "I am sorry, one more thing.", "Sorry for many requests
        -- at once.", "Sorry, that is two instructions."): they ask for nothing; an aside with a value, a name or
        -- a negation of its own ("if it is not possible, then ...") is no phrase of these and stays asked
        "if there is no problem", "if there's no problem", "if there is no issue", "if there's no issue",
        "if no problem", "if it is no problem", "if it's no problem", "if this is possible", "if this is ok",
        "if this is okay", "if this is alright", "if this is all right", "if it is ok", "if it is okay",
        "if it's ok", "if it's okay", "one more thing", "just one more thing", "one last thing",
        -- (the instructor's exercise named, "set the protected zone to three miles for this one")
        "for this one", "for that one", "for the next one",
        "sorry for many requests at once", "sorry for many requests", "sorry for so many requests",
        "sorry for the many requests", "sorry for all the requests", "sorry for many instructions",
        "sorry for so many instructions", "sorry to ask again", "sorry for asking again", "sorry for the trouble",
        "that is two instructions", "that's two instructions", "that is three instructions",
        "that's three instructions", "those are two instructions", "these are two instructions",
        -- the person who plays the pilot in a study ("the pilot participant for Skymark 711 has left")
        "pilot participant", "pilot participants" },
    -- the experimenter's account of a run in a remark beside a complete request, words that name no instruction,
    -- value, place or timing ("faster than I had intended", "we're comparing Mach cruise against fixed-CAS",
    -- "I'd like that to be reflected", "the transit phase", "I'll take a
    -- screenshot", "so aircraft disappear when they leave it"); each base form stands for its inflections
    experiment_prose = { "intend", "intention", "compare", "comparison", "reflect", "transit",
        "screenshot", "video", "disappear", "vanish" },
    -- the ordinary accompaniments of instructions: verbs of changing a setting, participles that
    -- introduce a value ("flying 180"), and nouns and verbs that frame a clearance ("avoiding action",
    -- "track direct", "to the left side", "the velocity")
    accompaniments = { "change", "changes", "alter", "adjust", "modify", "update", "amend", "make", "makes",
        "configure", "configures", "reconfigure",
        "shrink", "enlarge", "widen", "expand", "tighten", "relax", "margin", "buffer", "interval", "shorten",
        "lengthen", "extend", "extends", "extended",
        -- the dimensions of a setting ("the vertical size of the PZ")
        "size", "sizes", "dimension", "dimensions", "extent",
        -- a setting's work said formally ("resolutions computed with the MVP method", "perform conflict detection
        -- every two seconds", "which method is the simulator employing", "restore the zone to 5 NM")
        "compute", "computed", "computes", "computing", "perform", "performed", "performs", "performing", "employ",
        "employed", "employs", "employing", "restore", "restored", "restores",
        -- what a clearance is as a move ("the resolution manoeuvre", "avoidance maneuver")
        "manoeuvre", "manoeuvres", "maneuver", "maneuvers",
        -- an aircraft's present course described ("the Vueling's drifting off its route")
        "drifting", "drifted", "wandering", "straying", "deviating",
        "flying", "flew", "proceeding", "track", "tracking", "action", "side", "velocity", "instruction",
        "instructions", "clearance", "reclearance", "amendment", "reroute", "request", "requested", "automatic",
        "automatically", "auto", "manual", "manually",
        "default", "restriction", "unrestricted", "constraint", "divert", "diversion", "high", "low", "intersection", "ac", "acft",
        -- a speed named by the aircraft's configuration ("minimum clean speed, 210 knots")
        "clean",
        -- participles that place what follows ("located at NARIX"), and the experimenter's own aircraft
        "located", "positioned", "situated", "ownship",
        -- an aircraft described by its size ("the small Cessna", "a big Boeing") or its airline's country ("the
        -- German one, the Lufthansa"; names that are airlines' own, "Norwegian", "Swiss", are not here)
        "small", "little", "wee", "tiny", "big", "german", "swedish", "danish", "finnish", "dutch", "french", "spanish",
        "italian", "polish", "latvian", "lithuanian", "icelandic", "portuguese", "hungarian", "greek", "irish", "british",
        "chilean", "brazilian", "canadian", "mexican", "japanese", "australian", "vietnamese", "russian", "belgian",
        "czech",
        -- the margin a resolution keeps ("resolution margin factor 1.05")
        "margin",
        -- kinds of traffic, parts of the airspace, and what a vector avoids
        "arrival", "arrivals", "departures", "overflight", "overflights", "sector", "airspace", "area", "region",
        "atlantic", "pacific",  -- (oceans a position is said over: "over the Atlantic at 45N 30W")
        "danger", "restricted", "prohibited",
        "weather", "terrain", "storm", "cell", "cloud", "thunderstorm", "icing", "mountains", "mountain", "hills",
        -- what a shape drawn on the scope is for ("a reference line", "the sector boundary")
        "reference", "boundary", "border", "corner", "corners", "edge", "centre", "center",
        -- states and settings a request names ("which method is active", "the scenario file", "ADS-B noise")
        "active", "inactive", "enabled", "disabled", "file", "ads-b", "adsb", "colliding", "collision",
        "conflicting", "working", "functioning",
        -- the part of the simulation a setting belongs to ("turn on the conflict detection module")
        "module", "modules", "function", "functionality", "feature", "system", "logic",
        -- (a newcomer's words for the simulation and its conflict detection: "let the computer steer them apart",
        -- "turn on the crash warnings", "ten times faster than real life")
        "computer", "crash", "crashes", "life",
        -- verbs that go with an instruction's direction or place: informal ones ("bump the speed up", "crank
        -- the look-ahead up") and those of staying and going ("stay on 250 knots", "returning to Orly")
        "bump", "crank", "push", "knock", "dial", "stay", "remain", "return", "sit", "head", "hand",
        -- verbs that open the move an instruction names ("begin its descent to FL200", "commence descent")
        "begin", "begins", "commence", "commences", "initiate", "initiates",
        -- (Indian English "prepone the descent", "kindly prepone its climb": the move made earlier than
        -- planned; squawk's instruction runs at once, as "begin" it)
        "prepone", "prepones", "preponed",
        -- legs of an approach a vector is for ("vectors for base"), and alerts
        "base", "downwind", "final", "spacing", "sequencing", "alert",
        -- controllers' written abbreviations of instruction words
        "maint", "mnt", "dsc", "dsnd", "dscnd", "clmb", "degs", "vect", "vects", "vctr", "inc", "incr",
        -- squawk's own display, where a command shows or draws what it is asked, and the traffic on it
        -- ("put a Delta CRJ900 on the board", "remove the United from the scene", "to see the trajectories")
        "console", "screen", "display", "window", "map", "scope", "draw", "board", "scene", "trajectory",
        "trajectories",
        -- the experiment a request is made for ("for the next trial", "the participant keeps missing it", "seed
        -- 7 for reproducibility", "so I can check it against the script": the session's written plan)
        "script", "scripts", "protocol",
        "trial", "trials", "participant", "participants", "session", "sessions", "calibration", "experiment",
        "experiments", "reproducibility", "reproducible", "repeatability", "repeatable", "determinism",
        "deterministic",
        -- an airspace design put to the test ("we're evaluating reduced separation", "the one that tests the
        -- new branch", "the designer's note", "a quick check before we run"; a verb's plain form, "to test
        -- ...", is left to G:purpose)
        "tests", "testing", "tested", "evaluates", "evaluating", "evaluated", "evaluation", "assessing",
        "assessment", "validating", "validation", "designer", "designers", "designing", "designed", "quick",
        -- what an aircraft carries or flies for ("a B763 cargo", "a charter out of Katowice")
        "cargo", "freighter", "freight", "passenger", "passengers", "charter", "airliner",
        -- a human-factors study's instruments and measures ("the eye tracker is calibrated", "fill in the
        -- NASA-TLX", "so the geometry works", "the crossing angle")
        "eye", "tracker", "eye-tracker", "nasa", "tlx", "nasa-tlx", "questionnaire", "workload", "geometry",
        "calibrated", "crossing", "condition", "conditions", "baseline", "measurement", "measurements",
        -- (the traffic a workload study brings in by waves, its conditions with and without the resolver: "create the
        -- second wave aircraft EZY39GH ...", "phase 2 is the assisted condition")
        "wave", "waves", "assisted", "unassisted",
        -- (a reinforcement-learning evaluation's runs and models: "seed 42 so rollouts are reproducible", "new ep:
        -- seed 7", "policy v3 ckpt 2000")
        "rollout", "rollouts", "ep", "eps", "episodes", "checkpoint", "ckpt", "policy", "eval",
        -- (a student's coursework a request is made for: "for my homework exercise I need ...")
        "homework", "coursework", "assignment", "lecturer", "tutor",
        -- a part of the airspace a study is run in ("for the terminal area trials")
        "terminal", "en-route", "enroute",
        -- an incident investigation's reconstruction and its narration of what was cleared ("an additional
        -- aircraft", "was then given a descent to FL120", "a speed reduction to 250 knots")
        "reconstruction", "investigation", "investigators", "investigator", "additional", "given", "reduction" },

    -- prefixes of hyphenated words, written apart by the lexer ("co-altitude", "non-conflicting")
    prefixes = { "co", "non", "pre", "semi", "sub", "multi", "re" },
    -- an air traffic unit or setting named by its place ("New York departure", "Boston approach",
    -- "Kennedy altimeter"): the one or two words before these are its place
    facilities = { "departure", "approach", "center", "centre", "tower", "ground", "radar", "control",
        "delivery", "director", "information", "altimeter", "qnh", "oceanic", "radio",
        -- (Canada's terminal control unit: "Porter 225, Ottawa Terminal, descend ...")
        "terminal",
        -- (a unit by its abbreviation: "Barcelona ACC", "Madrid TWR")
        "acc", "twr", "uac" },
    -- words that end a station's name only in the addressing position (G:station_clause), set off by commas
    -- after the callsign: an area control sector ("Lion Inter 852, Makassar Area, descend ...") and the military
    -- radar units ("Tartan 61, London Military, identified, ..."); elsewhere English ("the military area")
    station_units = { "area", "military" },
    -- phrases that bound a value, lift its bounds or keep it in force ("or greater", "not less than",
    -- "climb without restriction", "until further advised"): the value is the instruction's, explained whole
    value_phrases = { "or greater", "or better", "or more", "or less", "or above", "or below", "at least",
        "at most", "not less than", "no less than", "not more than", "no more than", "until further advised",
        "until further notice", "without restriction", "without restrictions",
        -- the same said with "till", without "further", or with the verb unbent ("until further advise")
        "till further advised", "till further notice", "until advised", "till advised", "until further advise", "until further advice", "till further advice",
        "till further advise", "until further instructions", "till further instructions",
        -- (and "new" for "further", as Portuguese "até novas instruções": "maintain level 250 until new instructions")
        "until new instructions", "till new instructions",
        -- (the noun controllers of many regions use: "speed 280 knots until further advice")
        "until further advice", "till further advice", "until further clearance", "till further clearance",
        "until further notification", "until advised otherwise", "until otherwise advised",
        "unless otherwise advised", "unless advised otherwise",
        -- the same in ICAO English as a second language, "than" or the noun left out ("rate not less 1000 feet
        -- per minute", "maintain FL130 until further"), or the bound said before its value's noun ("not above
        -- speed 270")
        "not less", "not more", "until further", "till further", "not above speed", "not below speed",
        -- (what is left of a route, all of it still to fly: "delete the rest of your route")
        "rest of the route", "rest of your route", "rest of its route", "rest of his route", "rest of her route",
        "remainder of the route", "remainder of your route", "rest of the routing", "rest of the flight plan" },
    -- words that change what an instruction means: a leftover unless the parse carried them (a condition
    -- command, a switch turned off, a direct-to past a place, a handler that read it)
    negation = { "not", "instead", "don't", "dont", "doesn't", "didn't", "never", "unless", "cancel", "cancels", "cancelled", "canceled", "cancelling", "canceling",
        "undo", "can't", "cannot", "won't", "shouldn't", "mustn't", "isn't", "aren't", "wasn't", "without", "except" },
    condition = { "if", "after", "until", "till", "before", "once", "when", "whenever", "unless" },
    -- instruction words said bare (G:said_bare: alone in their clause beside an instruction, "climb FL300 cross",
    -- "KLM12 resume, climb FL300") that no command carries: asked, never dropped. `place`: a word whose value is a
    -- place ("cross", "proceed", "join"), asked for it; `meaning`: a word that may change what is flown
    -- ("resume", "continue", "cleared", a station named: "tower"), asked what it means (G:bare_asked: one straight
    -- before an instruction word is its manner, "continue climb", "cleared descend"); `after`: one asked only after
    -- the instruction's value. `place`, `meaning` and `after` are asked beside value instructions only (ALT, SPD,
    -- HDG, VS); `report`, `noun`, `area` and `put_off`, words no command reads, beside a direct-to's place and any
    -- other command too (G:unaccounted, G.bare_beside_place)
    -- words that a speaker who mixes L and R, or a recogniser hearing one, writes for a turn's side, straight after
    -- "turn" or before "turn", "heading" or "hdg" ("lite turn", "lift turn"): asked, never dropped and never guessed a
    -- side ("turn lift", a recogniser's "left" after "turn", and "turn light", a Japanese or Korean speaker's
    -- "right", are heard_as's)
    side_unsure = { "light", "lift", "lied", "lite" },
    bare_asked = {
      place = { "cross", "crossing", "proceed", "join", "joining", "rejoin", "rejoining", "intercept", "intercepting",
          "via", "route", "routing", "track", "follow", "avoid" },
      meaning = { "resume", "continue", "cleared", "recleared", "fly", "go", "enter", "leave", "establish",
          "established", "cancel", "cruise", "switch", "call", "activate", "deactivate", "enable", "disable", "start",
          "skip", "regain", "raise", "sink", "tower", "ground", "departure", "centre", "center",
          -- a check asked for ("climb FL300, check")
          "check", "verify" },
      -- a state reported as reached ("heading 090 done", "FL300 reached", "pause the simulation done": the speaker
      -- may report, not instruct), asked after the value, the callsign or (no aircraft named) the command's words
      report = { "reached", "done", "complete", "completed", "checked", "verified" },
      -- nouns of the traffic and the simulation that instruct nothing alone, asked after the value, the place or
      -- the callsign ("descend FL200 spacing", "direct WP2 fuel", "heading 090 wind"; "for spacing" is a purpose,
      -- read; opening the request, "Conflict 3, ...", a noun names what is addressed)
      noun = { "separation", "spacing", "sequence", "sequencing", "conflict", "conflicts", "fuel", "tanker", "scope",
          "wind", "winds", "high", "low" },
      -- the same of the airspace, said after a place its own ("at LAX airport"): asked after the value or callsign
      area = { "runway", "airport", "sector", "airspace" },
      -- (asked after a value only: "stop the Iberia's descent" is the instruction's verb, "sim speed half" the value)
      after = { "stop", "clear", "half", "level" },
      -- a time said after the value or (no aircraft named) the command's words, which puts the instruction off
      -- ("climb FL300 soon", "pause the simulation shortly"), where squawk sends it now; before the next
      -- instruction, "..., afterwards descend FL200", it orders them
      put_off = { "soon", "shortly", "afterwards", "afterward", "thereafter", "subsequently", "next", "twice" } },
  },
  -- letters with accents written as navdata writes names, in plain letters ("Düsseldorf" DUSSELDORF)
  accents = { ["à"] = "a", ["á"] = "a", ["â"] = "a", ["ã"] = "a", ["ä"] = "a", ["å"] = "a", ["ç"] = "c",
      ["è"] = "e", ["é"] = "e", ["ê"] = "e", ["ë"] = "e", ["ì"] = "i", ["í"] = "i", ["î"] = "i", ["ï"] = "i",
      ["ñ"] = "n", ["ò"] = "o", ["ó"] = "o", ["ô"] = "o", ["õ"] = "o", ["ö"] = "o", ["ø"] = "o", ["ù"] = "u",
      ["ú"] = "u", ["û"] = "u", ["ü"] = "u", ["ý"] = "y", ["ÿ"] = "y", ["ß"] = "ss", ["À"] = "A", ["Á"] = "A",
      ["Â"] = "A", ["Ä"] = "A", ["Å"] = "A", ["Ç"] = "C", ["È"] = "E", ["É"] = "E", ["Ê"] = "E", ["Ë"] = "E",
      ["Í"] = "I", ["Î"] = "I", ["Ñ"] = "N", ["Ó"] = "O", ["Ô"] = "O", ["Ö"] = "O", ["Ø"] = "O", ["Ú"] = "U",
      ["Ü"] = "U",
      -- (Turkish: the dotless and dotted i, g with breve, s with cedilla)
      ["ı"] = "i", ["İ"] = "I", ["ğ"] = "g", ["Ğ"] = "G", ["ş"] = "s", ["Ş"] = "S" },
  -- hesitations: skipped inside a spoken number, but a number said with one is not
  -- completed by guessing ("heading uh two two" asks which heading)
  -- (Irish and Scottish speakers write their hesitation "em")
  hesitations = { "ah", "uh", "um", "er", "eh", "em", "euh" },
  -- words that count the "thousand" after them ("two and a half thousand feet", "a few thousand feet"): no
  -- "thousand feet" said bare, read as one thousand, after them
  thousand_counted = { hundred = true, half = true, quarter = true, few = true, several = true, many = true,
                       couple = true, tens = true, t = true },
  -- typos are corrected to these words (one edit away, two for 7+ letters);
  -- short everyday words are left out: speech recognition makes real words
  -- near them ("loan", "train") far more often than typists misspell them
  spelling = {
    targets = { "climb", "descend", "descent", "maintain", "altitude", "heading", "speed", "knots", "reduce",
        "increase", "decrease", "delete", "remove", "waypoint", "direct", "create", "aircraft", "destination",
        "origin", "vertical", "simulation", "scenario", "turbulence", "conflict", "detection", "resolution",
        "separation", "radius", "angle", "callsign", "degrees", "feet", "thousand", "hundred", "expedite",
        "define", "teleport", "reposition", "lateral", "navigation", "enable", "disable", "seconds", "minutes",
        "timestep", "protected", "turn", "pause", "resume", "spawn", "generate", "latitude", "longitude",
        "minimum", "horizontal", "forward", "right", "left", "creconfs", "trail", "trails", "dtmult", "lookahead", },
    common = { "stop", "them", "last", "want", "have", "from", "with", "what", "also", "back", "give", "make",
        "take", "need", "into", "onto", "down", "more", "less", "keep", "this", "that", "were", "will", "sure",
        "would", "should", "could", "their", "there", "these", "those", "about", "after", "again", "both",
        "each", "other", "some", "such", "than", "very", "your", "name", "time", "home", "over", "plus", "runs",
        "show", "send", "sent", "held", "lead", "deletion", "circle", "lift", "rights", "lefts",
        -- (words one letter from "trail": "trial 3")
        "trial", "trials", "train", "trait",
        -- (a controller position named in a hand-off: "contact director 118.82")
        "director",
        -- (the opposite of "minimum", two letters from it: "at maximum rate")
        "maximum", },
  },
  -- instruction words of three letters or more that a typing slip one edit from them is read as, beside
  -- spelling.targets (translate/typos.lua: only in a request asked about, every reading of the slip tried), and
  -- how far from the traffic a fix, navaid or airport of the slip's letters keeps it as typed (nautical miles)
  typo_targets = { "and", "then", "fpm", "route", "hdg", "mach", "level", "proceed", "please", "move",
      -- (a pseudo-pilot's readback: "descnding FL90", "decsending FL140")
      "descending", "climbing", "reducing", "increasing", "turning", "maintaining",
      -- (a condition's verb: "pasing 8000 reduce 210"; "swich on conflict detction")
      "passing", "reaching", "leaving", "switch",
      -- (an experimenter's state question typed fast: "what is tap33 doin")
      "doing",
      -- ("contine present heading", "contnue on track")
      "continue" },
  typo_place_nm = 250,
  -- units after a value that keep "FL 2 10" two values ("fl 2 10 knots"): a level's figures are never split before them
  -- words that, straight after a split typed level, take it back (grammar.lua's split level check: "FL 16 0 - sorry,
  -- I mean one six zero" is the correction's to read)
  level_split_taken_back = { sorry = true, sry = true, correction = true, corr = true },
  level_split_units = { knots = true, kts = true, kt = true, knot = true, degrees = true, deg = true, nm = true,
                        miles = true, mile = true, minutes = true, min = true, seconds = true, sec = true, fpm = true,
                        feet = true, ft = true, percent = true },
  -- airport settings named before "A -> B" ("dest eidw -> einn"): changed from A to B
  arrow_settings = { dest = true, destination = true, orig = true, origin = true },
  -- settings named before an arrow and their value ("alt -> FL330"): the arrow is no direct-to
  -- words of an encounter's geometry said for aircraft created at random ("2 acft head-on", "converging",
  -- "10nm apart"), which MCRE cannot set
  random_geometry_words = { ["head-on"] = true, headon = true, converging = true, crossing = true, collision = true,
    apart = true, opposing = true, opposite = true, ["in-trail"] = true, encounter = true },
  direct_arrow_not = { alt = true, altitude = true, level = true, speed = true, heading = true, mach = true,
                       vs = true, fl = true },
  -- typed shorthand: a prefix written before its value, glued or apart
  -- ("s270", "h 240", "l330", "rod 1500"), stands for these words
  -- (a turn side typed without its vowels or cut short, "turn lft heading 200", "hdg 120 rgt", "turn lef 45", is
  -- that side)
  shorthand = { s = "speed", h = "heading", l = "left", r = "right", lt = "left", rt = "right", lft = "left",
                rgt = "right", rght = "right", lef = "left", spd = "speed",
                hdg = "heading",
                -- (two letters swapped, or the vowels left out: "hgd 240", "sdp 270", "rdc 250 kts")
                hgd = "heading", sdp = "speed", rdc = "reduce",
                rod = "rate of descent", roc = "rate of climb" },
  -- contractions a speech recogniser or a hurried typist writes without their apostrophe ("once youre at two
  -- fifty", "weve got a conflict", "whats DERLA's position"), read as the contraction: only forms that are no
  -- English word and no navaid's ident ("were", "well", "ill", "its", "lets", "hell", "shell", "wed", "id",
  -- "wont" and "im", the IM NDBs, stay as written)
  apostrophe_dropped = { youre = "you're", youve = "you've", youll = "you'll", youd = "you'd", weve = "we've",
                         theyre = "they're", theyve = "they've", theyll = "they'll", ive = "i've", itll = "it'll",
                         whats = "what's", thats = "that's", theres = "there's", wheres = "where's",
                         heres = "here's", dont = "don't", doesnt = "doesn't", didnt = "didn't", cant = "can't",
                         isnt = "isn't", arent = "aren't", wasnt = "wasn't", werent = "weren't", hasnt = "hasn't",
                         havent = "haven't", couldnt = "couldn't", wouldnt = "wouldn't", shouldnt = "shouldn't" },
  -- controllers' typed abbreviations of instruction words (text ATC on the online networks), read as the
  -- words they stand for where a word beside them shows the instruction: `word`, the words read; `next` /
  -- `prev`, words one of which must be the next / the previous word ("#number": a value typed with digits,
  -- "fl180" too; "#place": see pd; "#start": the line's first word or one after punctuation, for `prev`; "#end":
  -- none, the abbreviation closing its clause, for `next`);
  -- `after_next`, the same of the word after next (a callsign between: "trn hop7 rgt 20"); a list of such
  -- readings is tried in order; `not_prev` / `not_next`, words before / after it that keep it as typed (with
  -- `full_run`, a count, not_next keeps it only after that many words of `prev` in a row); `hundreds`, a verb of a level change
  -- typed short, after which two typed digits of 30 to 99 are hundreds of feet as on a flight strip ("dn 60":
  -- 6000 ft; "dn 12", 1200 ft or 12000 with a digit lost, stays as typed, and asked); "#name", for `next`, a
  -- word of two to five letters in any case (a fix's ident typed in lower case); "#callsign", three letters and
  -- digits ("sas471", "ezy45lc"); "#waypoint", a word of two to five letters, the last may be a digit ("dpk",
  -- "pt1"). Elsewhere it stays as typed ("direct
  -- TRN" is Turnberry, "trail red" a colour, "Red Cap" an airline).
  typed_abbreviations = {
    -- (the tens of Belgian and Swiss French said in English: "flight level two hundred septante", "nonante degrees")
    septante = { word = "seventy" }, huitante = { word = "eighty" }, octante = { word = "eighty" },
    nonante = { word = "ninety" },
    -- (in capitals an ident, "define a point EXPD at ...")
    expd = { word = "expedite", caps_kept = true }, expdt = { word = "expedite", caps_kept = true },
    til = { word = "until", not_prev = "legg" },
    -- (a condition typed short: "ryr7fg whn spd 250 climb fl260")
    whn = { word = "when" },
    sched = { word = "schedule", next = "#number hold pause ff t at in" },
    -- ("turn on conflict res", "cd and res on": resolution after the conflict's words)
    res = { word = "resolution", prev = "conflict conflicts cd detection and" },
    -- ("dt mult back to 1", "sim speed mult 2": the clock's multiplier)
    mult = { word = "multiplier", prev = "dt time sim simulation speed" },
    maint = { word = "maintain", next = "#number fl flight speed spd heading hdg altitude alt level present own" },
    mnt = { word = "maintain", next = "#number fl flight speed spd heading hdg altitude alt level present own" },
    -- (the vowels left out of a level change: "dsnd 5000", "clmb fl240")
    dsnd = { word = "descend", next = "#number fl flight level to", hundreds = true },
    dscnd = { word = "descend", next = "#number fl flight level to", hundreds = true },
    dsc = { word = "descend", next = "#number fl flight level to", hundreds = true },
    -- (US en-route shorthand, "dn fl240", "dn 110": descend; after a rate's or a speed's name, "vs dn 1500",
    -- it is "down", and stays as typed)
    dn = { word = "descend", next = "#number fl flight level to", not_prev = "vs rate speed spd mach turn",
           hundreds = true },
    clmb = { word = "climb", next = "#number fl flight level to", hundreds = true },
    -- ("over cmb fl240": after a word of place it is the Cambrai navaid)
    cmb = { word = "climb", next = "#number fl flight level to", hundreds = true, caps_kept = true,
            not_prev = "over at via dct direct to from after before" },
    -- (a pseudo-pilot's "ffwd 5 min", "mk sas9 crj9 ...", "conflict det on")
    ffwd = { word = "fast forward" },
    mk = { word = "make", prev = "#start", caps_kept = true },
    det = { word = "detection", prev = "conflict cd" },
    trn = { { word = "turn", next = "left right lft rt lt rgt l r hdg heading" },
            { word = "turn", prev = "#start", after_next = "left right lft rt lt rgt l r hdg heading" } },
    -- (an experimenter's shorthand of the command words: "head 030", "incr 280", "rm ooabc", "del rte",
    -- "lvl?", "vert sep 2000ft", "KLM12 rm wpt SPY", "KLM12 rm SPY from rte", "sas471 rm pt1"; "head" before no
    -- number, "rm" inside a line before no waypoint word, no "from" after the next and not between a callsign and
    -- an ident, and "del" before no route word stay as typed; "lvl"
    -- after a place's verb is the LVL navaid)
    head = { word = "heading", next = "#number" },
    incr = { word = "increase", next = "#number speed spd to" }, inc = { word = "increase", next = "#number speed spd to" },
    decr = { word = "decrease", next = "#number speed spd to" },
    rm = { { word = "remove", prev = "#start" }, { word = "delete", next = "wpt waypoint" },
           { word = "remove", after_next = "from" }, { word = "remove", prev = "#callsign", next = "#waypoint" } },
    -- ("ezy45rt whr is it now", "wht is klm12 doing": the question's word typed without its vowels)
    whr = { word = "where", next = "is are's" }, wht = { word = "what", next = "is are's" },
    -- ("make it the del area", "box ... -> del area": the deletion area, no aircraft deleted)
    del = { { word = "delete", next = "rte route wpt waypoint" }, { word = "deletion", next = "area" } },
    -- ("rem EZY88": remove, opening the line; "rnd traffic 5 a/c": random before the traffic it makes)
    rem = { word = "remove", prev = "#start" },
    rnd = { word = "random", next = "traffic aircraft" },
    rte = { word = "route" },
    -- ("add wp sopok", "new wp ctr at 52.31n 4.76e": a waypoint typed short after a verb or an article; elsewhere,
    -- or before a number, "add wp one two" (a user waypoint WP12), it stays as typed)
    wp = { word = "waypoint", prev = "add new a the",
           not_next = "#number zero one two three four five six seven eight nine niner" },
    lvl = { word = "level", not_prev = "dct direct to via add after over cross at" },
    -- (a researcher's shorthand of the resolution settings: "horiz resolution factor 1.1", "hor reso factor 1.05")
    horiz = { word = "horizontal", next = "sep separation resolution reso res" },
    hor = { word = "horizontal", next = "sep separation resolution reso res" },
    reso = { word = "resolution", prev = "horizontal vertical horiz hor vert conflict cd" },
    sep = { word = "separation", prev = "vertical horizontal lateral min minimum" },
    tl = { word = "turn left", next = "#number hdg heading" }, tr = { word = "turn right", next = "#number hdg heading" },
    fh = { word = "fly heading", next = "#number" },
    rsm = { word = "resume", next = "own normal nav navigation route speed" }, ctc = { word = "contact" },
    dm = { word = "descend and maintain", next = "#number fl flight", hundreds = true },
    cm = { word = "climb and maintain", next = "#number fl flight", hundreds = true },
    recl = { word = "recleared", next = "#number fl flight" }, rv = { word = "radar vectors", next = "hdg heading" },
    blw = { word = "below", next = "#number fl flight" }, abv = { word = "above", next = "#number fl flight" },
    -- ("Cool Red 2505" is Philippines AirAsia's telephony)
    red = { word = "reduce", next = "#number spd speed to", not_prev = "trail colour color a in cool" },
    -- (several readings: the first whose neighbours fit; "#place", three to five capital letters, a fix,
    -- navaid or airport typed as its ident: "pd FIGGY" is "proceed direct FIGGY", "pd figgy" stays as typed)
    pd = { { word = "pilot's discretion", prev = "desc descend dsc dscnd dsnd climb clb clmb",
             next = "#number fl flight" },
           { word = "proceed direct", next = "#place", not_prev = "desc descend dsc dscnd dsnd climb clb clmb" },
           -- (after the level or the rate it qualifies, "dn fl300 pd", "dm 140 at 2000 fpm pd")
           { word = "pilot's discretion", prev = "#number fpm ft feet" } },
    -- (FAA typed shorthand: "rs 210" reduce speed; "exp ILS" expect; "hvy" heavy; "8 thsnd" eight thousand;
    -- "adn" and; "ADN" in capitals is the ident of a fix, ADN near Monterrey)
    rs = { word = "reduce speed", next = "#number to" },
    -- ("SAS902 x NAXEL @ FL200": "x" before a fix's ident is "cross")
    x = { { word = "cross", next = "#place" },
          -- (a fix typed in lower case, then the value to cross it at: "x lendy at 110", "x alb 110")
          { word = "cross", next = "#name", after_next = "at #number" } },
    -- (and after a level or value closing its clause, "desc fl200 exp", expedite)
    -- ("exp clb fl200", "desc 4000 exp 2500 fpm": before a climb or a descent, or a rate, expedite)
    exp = { { word = "expedite", next = "clb climb desc descend dsc dsnd clmb dn" },
            { word = "expedite", next = "#number", after_next = "fpm ft/min" },
            { word = "expect", next = "ils rnav vis visual loc rwy runway approach app #number" },
            { word = "expedite", prev = "#number", next = "#end" } },
    hvy = { word = "heavy" }, adn = { word = "and", caps_kept = true },
    -- (a pseudo-pilot's "hdg 210 clrd ils 18r")
    clrd = { word = "cleared" },
    -- (an experimenter's "CD&R" typed short: "cdr on with MVP resolution", "turn cdr off")
    cdr = { word = "conflict detection and resolution" },
    -- (chat's "n" for "and" between a value and the next instruction, "desc fl160 n spd 250", "spd 210 n hdg
    -- 090"; before a number it is a hemisphere, "52.3 n 4.7 e", and after a word no value, "ba 123 n", it stays)
    n = { word = "and", prev = "#number",
          next = "@instruction_nouns climb clb desc descend dsc turn contact ctc direct dct dir reduce increase vs" },
    -- (US en-route shorthand: "tl 20 trfc" traffic; "rchg fl240 spd 250", "lvg fl270 spd 270" a level reached or
    -- left; "vctr alb" vectors; "whats ur alt" your; "fph" fly present heading (after no number: "1800 fph" is a slip of fpm); "all acft"; "20 rt" a turn's side after its degrees; "corr" correction;
    -- "ff 1 hr"; "5 fnl" final; "trls off" the trails; "mv" move, opening the line)
    trfc = { word = "traffic" }, rchg = { word = "reaching" }, lvg = { word = "leaving" },
    fph = { word = "fly present heading", not_prev = "#number" }, acft = { word = "aircraft" },
    -- ("enable vertical resos": the resolutions, a plural of "reso" typed)
    resos = { word = "resolutions" },
    rt = { word = "right", prev = "#number deg degrees" }, lt = { word = "left", prev = "#number deg degrees" },
    -- (the side typed without its vowels after the degrees of a turn, "25 lft", "10 deg rgt")
    lft = { word = "left", prev = "#number deg degrees" }, rgt = { word = "right", prev = "#number deg degrees" },
    rght = { word = "right", prev = "#number deg degrees" },
    corr = { word = "correction" }, hr = { word = "hour", prev = "#number" }, hrs = { word = "hours", prev = "#number" },
    fnl = { word = "final" }, trls = { word = "trails" }, mv = { word = "move", prev = "#start" },
    vctr = { word = "vectors" }, vect = { word = "vectors" }, vects = { word = "vectors" },
    ur = { { word = "your", prev = "whats what's what is say report" },
           { word = "your", next = "number speed spd level altitude alt heading hdg destination dest origin route "
             .. "position", caps_kept = true },
           -- ("once ur below 10k", "when ur at 250": "you're" after a condition's word)
           { word = "you're", prev = "once when after until till if as", caps_kept = true } },
    -- the online networks' text-speak (VATSIM, IVAO): "ur" before "number" or a value's noun is "your" ("ur number
    -- 1", "ur speed"); "r u" is "are you" ("how fast r u going"); "wats" is "what's"; "m8" is "mate"; "cfl", the cleared flight
    -- level of a network's controller client, before its level ("cfl 11000", "cfl fl150") is the altitude
    -- cleared; typed in capitals each is an ident and stays as typed
    -- ("once u get down to 5k", "can u spawn ...": "u" after a condition's word or a request's verb)
    r = { word = "are", next = "u", caps_kept = true },
    u = { { word = "you", prev = "are", caps_kept = true },
          { word = "you", prev = "once when after until till if can could would will", caps_kept = true } },
    wats = { word = "what's", caps_kept = true }, m8 = { word = "mate" },
    -- (a texting student's spellings: "yes im sure", "gimme 250 knots")
    im = { word = "i'm", caps_kept = true }, gimme = { word = "give me" },
    cfl = { word = "altitude", next = "#number fl flight", caps_kept = true },
    -- ("bel3qt tgt fl200 vs 1500": the level a climb or descent targets; "tgt ezy503" in a conflict set up)
    tgt = { word = "target" },
    -- ("crecon dlh602 a320 tgt ezy503 dpsi 180 ...": CRECONFS typed short)
    crecon = { word = "creconfs" },
    thsnd = { word = "thousand", prev = "#number" }, thsd = { word = "thousand", prev = "#number" },
    -- (hesitations typed as said: "mach .. erm spd 270"; a typed "err" or "sry" is "sorry": what follows it
    -- corrects what it follows, "fl130 err fl150", "dir ridar err rokil")
    err = { word = "sorry" }, sry = { word = "sorry" }, erm = { word = "uh" }, umm = { word = "uh" }, uhh = { word = "uh" },
    uhm = { word = "uh" }, ehm = { word = "uh" }, ahh = { word = "uh" }, ahm = { word = "uh" },
    -- (a French speaker's hesitation, said in English as "uh": "Swiss 77, euh, heading 240")
    euh = { word = "uh" }, heu = { word = "uh" },
    -- (and "alors", so: "climb FL150, alors, one six zero, pardon")
    alors = { word = "uh" },
    -- French-accented English typed as heard: the h dropped ("turn left 'eading 060", "say 'eading"), the vowel
    -- of "turn" ("tourn left"), "ze" and "zen" for "the" and "then" ("pause ze simulation"), and "height" for "eight" inside a number
    -- said digit by digit or before "thousand"/"hundred" ("tree tree height", "descend to height thousand";
    -- after three digits said and before a typed number "height" is the level's noun: "heading three three zero
    -- height 5100 metres", "tree tree height 10000 feet" heading 338;
    -- elsewhere "height" is the altitude's name and stays, "zone half height thousand feet" too)
    -- Nigerian Pidgin in a Nigerian or Ghanaian controller's English: "wan" is "want" ("i wan check something";
    -- "dey", the verb "be", is an auxiliary), "wetin" is "what", and "do" after "dey" is "doing" ("wetin Arik
    -- 104 dey do": what is it doing)
    wan = { word = "want", prev = "i we you dem una" },
    wetin = { word = "what" },
    ["do"] = { word = "doing", prev = "dey" },
    eading = { word = "heading" }, tourn = { word = "turn" },
    -- ("vert sep", "vert reso", "reso mvp, vert on": vertical, shortened)
    vert = { word = "vertical" },
    ze = { word = "the", caps_kept = true }, zen = { word = "then", caps_kept = true },
    height = { { word = "eight", next = "thousand hundred", not_prev = "half zone vertical the" },
               { word = "eight", prev = "zero one two three tree four fower five fife six seven eight nine niner",
                 not_next = "#number", full_run = 3 } },
    -- Scots words, each read as the one English word it stands for ("gie it 250 knots", "slow it tae 230", "send
    -- it intae Newcastle", "drop ROBEM fae the route", "move it back oot", "whit level's the KLM at", "the A320 wi
    -- the Lufthansa colours", "descend FL70, naw, FL80", "haud on", "nae rush", "och", "aye, take the Loganair
    -- down", "the wee Saab", "the big yin", "what's it at the noo"). `caps_kept`: typed in capitals it is an
    -- ident and stays as typed ("remove TAE from the route": the OITA VOR); a navaid's ident (TAE, WI, AYE, YIN)
    -- also stays after a word that names a place ("direct tae", "via wi")
    gie = { word = "give", caps_kept = true }, gies = { word = "give us", caps_kept = true },
    tae = { word = "to", not_prev = "direct dct dir via to at over after cross from", caps_kept = true },
    intae = { word = "into", caps_kept = true }, ontae = { word = "onto", caps_kept = true },
    fae = { word = "from", caps_kept = true }, oot = { word = "out", caps_kept = true },
    whit = { word = "what", caps_kept = true },
    wi = { word = "with", not_prev = "direct dct dir via to at over after cross from", caps_kept = true },
    naw = { word = "no", caps_kept = true }, nae = { word = "no", caps_kept = true },
    haud = { word = "hold", caps_kept = true },
    -- ("och" opening a sentence is the Scots "oh"; between words it is Swedish "and", lexicon.said_whole.nordic's)
    och = { word = "oh", prev = "#start", caps_kept = true },
    aye = { word = "yes", not_prev = "direct dct dir via to at over after cross from", caps_kept = true },
    -- (Turkish "evet", yes, and "hayır", no, said in an English clearance or as the answer to squawk's question:
    -- "evet, Turkish 6RT descend ...", "climb FL110, hayır, FL100"; in capitals or after a place's verb they stay)
    evet = { word = "yes", not_prev = "direct dct dir via to at over after cross from", caps_kept = true },
    hayir = { word = "no", not_prev = "direct dct dir via to at over after cross from", caps_kept = true },
    -- (an Israeli controller's Hebrew in an English clearance: "ken", yes; "lo", no; "beseder", all right; "rega",
    -- wait a moment: "El Al 315, ken, descend 4000", "descend FL80, rega, lo, FL90", "heading 170, lo, left heading
    -- 100", "rega, pause"; in capitals or after a place's verb they stay, as an ident)
    ken = { word = "yes", not_prev = "direct dct dir via to at over after cross from", caps_kept = true },
    lo = { word = "no", not_prev = "direct dct dir via to at over after cross from", caps_kept = true },
    beseder = { word = "okay", not_prev = "direct dct dir via to at over after cross from", caps_kept = true },
    rega = { word = "wait", not_prev = "direct dct dir via to at over after cross from", caps_kept = true },
    wee = { word = "small", caps_kept = true },
    yin = { word = "one", prev = "big wee small the that this", caps_kept = true },
    noo = { word = "now", prev = "the", caps_kept = true },
    -- (Indian English "revert" for "reply", the aircraft's own value asked for: "revert your level", "revert with
    -- your present speed", or closing its clause after a question the request asked ("what's your speed, revert",
    -- "confirm level and revert", `asked_before`); "revert to heading 270" and "climb FL200, revert" stay as said,
    -- and asked)
    revert = { { word = "report", next = "your" }, { word = "report", next = "with" },
               { word = "report", next = "#end please", asked_before = "what what's whats confirm say verify how" } },
    -- (a vertical rate's bound typed before its value: "RoD max 1500", "RoC min 500")
    rod = { word = "rate of descent", next = "max maximum min minimum" },
    roc = { word = "rate of climb", next = "max maximum min minimum" },
    -- (the flight management computer's page typed by its name: "show me the FPLN")
    fpln = { word = "flight plan" },
    -- ("when thru fl260 reduce 260": a level passed, typed short; "a route thru rober then parch")
    thru = { word = "through" },
    -- a game programmer's words for a turn, a heading and a vertical speed ("rotate 90 clockwise", "set its
    -- rotation to 090", "vertical velocity 0"): clockwise is a right turn
    clockwise = { word = "right" }, cw = { word = "right", prev = "#number" },
    counterclockwise = { word = "left" }, anticlockwise = { word = "left" }, ccw = { word = "left", prev = "#number" },
    rotation = { word = "heading", next = "to #number of" },  -- ("rotation speed", Vr, stays as typed)
    velocity = { word = "speed", prev = "vertical" },
    -- (Italian "quota", the altitude: "the quota put it at 9000 feet", "its quota 5000"; after no article or
    -- possessive and before no number it stays as typed, and asked)
    quota = { { word = "altitude", prev = "the its his her what which" }, { word = "altitude", next = "#number" } },
    -- (a collision volume, "the hitbox radius", "vertical hitbox 1000 ft": the protected zone)
    hitbox = { word = "protected zone" },
    -- ("make the separation bubble 3 nm", "the safety bubble", "make the bubble 3 miles": the protected zone around
    -- each aircraft; with an aircraft named and no zone's value, the setting asks which value is meant)
    bubble = { word = "protected zone", prev = "separation safety the" },
    -- ("the vertical bit, 500 feet either side", "the horizontal bit, 3 miles": the zone's dimension named in plain
    -- words; "a bit" of anything else stays as said)
    bit = { word = "zone", prev = "vertical horizontal lateral" },
    -- ("stretch the look-ahead to 8 minutes", "stretch the bubble"): a setting lengthened; "stretch" said of
    -- anything else (an aircraft's downwind, its speed) stays as said, and asked
    -- ("speed the whole thing up, ten times", "slow the whole lot down"): the simulation, said whole before the
    -- particle of a rate's change; "the whole thing" anywhere else stays as said
    thing = { word = "simulation", prev = "whole", next = "up down" },
    lot = { word = "simulation", prev = "whole", next = "up down" },
    stretch = { { word = "extend", next = "the", after_next = "look-ahead lookahead look bubble zone protected" },
                { word = "extend", next = "look-ahead lookahead look" } } },
  -- words that, typed before "=", name a setting or a value ("pz=5nm", "lookahead=300", "altitude=fl300"), beside
  -- the registry's names and the shorthand
  setting_keys = { "pz", "rpz", "lookahead", "altitude", "speed", "heading", "level", "fl", "mach", "rate",
                   "multiplier", "speedup", "timestep", "step", "radius", "cd", "cr" },
  -- labels of text for the log, before a colon opening the request ("log: seed=7 baseline"): kept as typed
  note_labels = { note = true, log = true, comment = true, message = true, memo = true, echo = true },
  -- the words an instruction is named by when it is said with no verb ("at ELDAR speed 250", "at BRAVO:
  -- altitude FL300"): a value there, said so, is the constraint at the waypoint, not an instruction to start
  instruction_nouns = { "speed", "spd", "altitude", "alt", "level", "fl", "flight", "heading", "hdg", "mach" },
  -- words that open a condition: "when AC01 reaches FL200, ..."
  condition = { "when", "once", "after" },
  -- the main clause's subject and modal after a condition, German word order ("when it has reached 300 knots, it
  -- shall climb to FL350"; G:subject_after_condition)
  main_clause_subjects = { "it", "he", "she", "they", "both" },
  main_clause_modals = { "shall", "should", "will", "must", "can" },
  -- words that, opening the clause after a diversion and its comma, make it no reason but when or where it
  -- happens ("divert to EDDK, at TAU", "send it to MUC, after KERAX": asked; grammar.lua G:diversion_reason)
  diversion_not_reason = { "at", "after", "over", "passing", "abeam", "when", "once", "before", "by", "via",
                           "leaving", "reaching", "until", "till", "in", "on", "then", "and" },
  -- words that limit an instruction to a condition said after it ("descend FL200, but only after BETOS", "climb
  -- FL300 only when it is over BUMIL": grammar.lua G:trailing_fix)
  condition_limiting = { "but", "only", "just" },
  -- words saying an instruction runs at once, closing a condition said after the instruction before ("descend FL320
  -- once it has slowed to 260 knots, and reduce to 260 knots now": grammar.lua G:condition_closed)
  at_once_words = { "now", "immediately", "already" },
  -- the words of a speed instruction that give its direction, said between its word and its value ("reduce 40
  -- knots", "speed up 50 knots", "slow down 30"): handlers_values.lua m:speed_change_read
  speed_direction_verbs = { "reduce", "reducing", "decrease", "decreasing", "increase", "increasing", "accelerate",
                            "decelerate", "slow", "slowing", "add", "up", "down", "faster", "slower" },
  -- verbs that make a bare number in a condition a speed ("once AFR1023 slows to 250")
  speed_verbs = { "slows", "slowed", "slow", "slowing", "accelerates", "accelerated", "accelerating", "decelerates",
    "decelerated", "decelerating", "reducing", "reduced", "reduce", "reduces", "decreased", "decreases" },
  -- words before a level that make the next instruction wait for it
  -- ("when passing flight level 130 reduce speed 250": ATALT)
  level_condition = { "when", "once", "passing", "leaving", "reaching", "after", "levelling", "leveling" },
  -- words between such a level and the instruction word that waits for it, part of the instruction
  -- ("when passing FL90 fly heading 090", "after passing FL100 resume own navigation direct HEMEL", "when at
  -- 12000 set speed 240", "once you're at 250 start down to FL100": a verb of starting before a level change's
  -- "down" or "descending")
  -- ("track direct", Australian; "go direct", "head direct": a direct-to's verbs)
  condition_lead = { "fly", "turn", "proceed", "route", "resume", "own", "navigation", "then", "set", "start",
                     "begin", "track", "go", "head" },
  -- before the level an aircraft leaves, said with the one it is cleared to ("leaving FL260 for FL200")
  level_left = { "leaving", "passing", "vacating" },
  -- the listener's convenience after "when you", "once you" ("when you get a sec", "once you have a moment",
  -- "when you're free"): one of these among the four words after "you" makes the clause a courtesy, explained
  -- (G:meaning_carried); any other "when you ..." ("when you are with the tower", "once you see the field") is a
  -- condition squawk reads only of a level, speed, place or distance, else asked
  convenience = { "sec", "secs", "second", "seconds", "moment", "minute", "chance", "time", "ready", "free", "able",
                  "can", "could" },
  -- a climb or descent left to the pilot ("descend when ready"): said with no level, asked about
  discretion = { "when ready", "when able", "when you're ready", "when it's ready", "when it is ready", "when it's able",
                 "when it is able", "at pilot's discretion", "at your discretion",
                 "at your own discretion", "at own discretion", "pilot's discretion" },
  -- the end of a limit until a place said after it, closing the request ("maintain 270 knots until SUNSS; thereafter
  -- it may fly at its own discretion", "... until CIVET, and then resume its normal speed"): an opener, then only
  -- `words`, one of `release` among them (G:limit_released)
  -- where an aircraft flies on after an instruction, said of it as a fact ("KLM12 at SPY speed 200, after that he
  -- goes to EHAM"): an opener ("after that" too), a pronoun, a verb and "to", then the place (G:onward_remark)
  onward = { openers = { "then", "afterwards", "afterward", "thereafter" },
             subjects = { "he", "she", "it", "they" },
             verbs = { "goes", "flies", "heads", "continues", "proceeds", "is going", "is heading", "will go",
                       "will fly", "will continue" } },
  limit_release = { openers = { "then", "thereafter", "afterwards", "afterward" },
                    words = { "it", "may", "can", "is", "free", "to", "fly", "at", "its", "own", "their", "his", "her",
                              "your", "pilot's", "pilots", "pilot", "discretion", "resume", "resumes", "normal",
                              "usual", "speed", "speeds", "no", "restriction", "restrictions", "the", "be", "then",
                              "again", "back", "up", "him", "them", "you", "do", "as", "per", "procedure",
                              "published" },
                    -- ("then it is up to him": the speed left to the pilot; "after that it is free", "then you can
                    -- do normal speed", "thereafter as per the procedure")
                    release = { "discretion", "normal", "usual", "restriction", "restrictions", "up", "free",
                                "procedure" } },
  -- before an instruction word: the instruction is only announced, not given
  not_a_clearance = { "expect" },
  -- a clause opening with one of `opens` (or of `with_is` and "is" or "about"), the aircraft it asks about straight
  -- after it ("is KLM12 at FL300?", "what's RYR2BA at FL300", "does X climb FL340?"), asks about the aircraft's state:
  -- no instruction (G:state_question). "what's" reads as "what"; "have X climb" instructs. "that" or "the" may come
  -- between ("is that KLM12 at FL300?"); an aircraft called before it or at its end is asked about as "you" ("KLM12,
  -- are you at FL300?", "are you at FL300, KLM12?")
  state_question = { opens = { "is", "are", "was", "were", "does", "do", "did", "has", "what", "how" },
                     -- ("why is KLM12 climbing to FL300?", "where is KLM12 going, EHAM?": asked, or shown)
                     with_is = { "what", "how", "why", "where" } },
  -- interjections said before a question about a setting ("hmm wait is conflict detection even on rn?"): passed
  -- over to find the question's first word, which decides whether the setting is asked about or switched
  -- verbs that change a setting; a request opening "is"/"are" with none of them asks about a value (G:setting_question)
  setting_verbs = { "set", "change", "make", "increase", "decrease", "reduce", "raise", "lower", "put", "switch",
    "turn", "bring", "double", "halve", "adjust", "reset", "keep" },
  setting_question_interjections = { "hmm", "hm", "wait", "oh", "ooh", "ah", "hey", "well", "alright", "ok", "okay",
                                     "so", "um", "uh", "erm", "ehm" },
  -- the copulas of a question about a setting in a statement's word order, its name before them ("the detection is
  -- on?", "detection's on?": m:statement_order_question)
  setting_question_copulas = { "is", "are", "isn't", "aren't" },
  -- the words that, within four words before the noun of a request said before ("it does not have a route", "it
  -- has no route", "never mind the route"), take that request back (G:withdrawn)
  withdrawn = { "not", "no", "never", "nevermind", "nvm", "doesn't", "doesnt", "hasn't", "hasnt", "don't", "dont",
                "isn't", "isnt", "without" },
  -- the words of a polite opener that asks leave to act ("is it possible to", "is it ok to"): the instruction after
  -- it is requested, not asked about (m:request_start, m:nav_asked)
  leave_asked = { "possible", "ok", "okay", "alright", "feasible", "trouble" },
  -- a wish framed before "if" that asks for the instruction after it ("it would be good if KLM12 climbs to FL300",
  -- "it is better if ...", "I would be grateful if ...": G:wish_frame): the evaluative words, one of which the
  -- frame holds, and the negations that make it no wish ("it would not be good if ...": asked)
  wish_evaluative = { "good", "nice", "great", "better", "best", "fine", "helpful", "useful", "ideal", "preferable",
                      "perfect", "wonderful", "excellent", "grateful", "thankful", "glad", "happy", "appreciate",
                      "appreciated", "prefer", "prefered", "preferred" },
  -- the nouns of what is given again to another aircraft ("the same instruction for DLH6CK": G:same_opening)
  same_given = { "instruction", "instructions", "thing", "clearance", "clearances", "command", "commands", "order",
                 "orders" },
  -- the nouns that make "same" a comparison of values ("the same level as", "same speed"): no aircraft said with
  -- it is told to do the same (G:same_doer)
  same_compared = { "level", "levels", "altitude", "altitudes", "height", "speed", "speeds", "heading", "headings",
                    "track", "course", "route", "routes", "flight", "fl", "mach", "rate", "position", "direction",
                    "time", "destination", "type", "spot", "place", "point", "waypoint", "fix", "airway", "runway" },
  wish_negation = { "not", "no", "never", "wouldn't", "wouldnt", "isn't", "isnt", "won't", "wont", "don't", "dont",
                    "couldn't", "shouldn't", "neither", "nor" },
  -- the states a word's "'s" stands before as "is" ("detection's on?", "resolution's switched off": no possessive;
  -- "active" is none, "the United's active waypoint")
  state_after_s = { "on", "off", "enabled", "disabled", "switched", "turned" },
  -- a pilot's question back to the controller, no instruction (G:question_back): "say again (the level)"
  -- with no value in its clause asks for a repeat; "confirm cleared FL200?", "confirm heading 270?", "verify assigned
  -- altitude FL300" with a value
  -- asks whether a clearance stands. Not after `not_after` ("I say again 260" is the controller's own repeat).
  -- A clause ending in "?" that holds one of `past` asks what was done before ("which one did Pablo use last
  -- week?"): a question, no instruction. A repeat asked with one of `addressed` after it ("say again your
  -- speed") is the controller asking the aircraft for its own value: a report, read as "say your speed".
  question_back = { repeat_words = { "say again", "say that again" }, confirm = { "confirm", "verify" },
                    not_after = { "i", "we" }, past = { "did", "didn't" }, addressed = { "your" } },
  -- the wrong value a pilot read back, named by the controller after the corrected instruction ("descend and
  -- maintain 6000, you said seven", ", readback was one one thousand"): each phrase, after a comma, opens a
  -- clause of values only that ends the request or its sentence (G: readback_heard)
  readback_heard = { "you said", "you read back", "you read", "you readback", "you read it back as", "readback was",
                     "read back was", "your readback was", "he read back", "pilot read back" },
  -- a readback reported by a third person, then what was cleared ("KLM12 read back FL110, he was cleared FL90, fix
  -- it": grammar.lua readback_reported): the verbs of the readback, who was cleared, the words between them and
  -- "cleared", and the words closing the request that ask for the clearance to be flown
  -- (the longer of two phrases that begin alike first)
  readback_reported = { verbs = { "read it back as", "read back as", "readback was", "read back was", "read back",
                                  "readback" },
                        cleared = { "he was", "she was", "it was", "they were", "he's", "she's", "it's", "was",
                                    "but he was", "but she was", "but it was", "but was", "but" },
                        fix = { "fix it", "fix that", "correct it", "correct him", "correct her", "correct that",
                                "please fix it", "please correct it" },
                        -- the words a value is said with ("flight level one one zero", "heading 200")
                        nouns = { "fl", "flight", "level", "heading", "speed", "mach", "altitude", "feet", "ft", "knots",
                                  "kt", "kts", "thousand", "hundred" } },
  -- an aircraft named straight after one of these is left out of the request (G:forgotten): "forget the Iberia"
  forget = { "forget" },
  -- an aircraft named as the subject of one of `described` is described, not instructed (G:described): "X and Y are
  -- co-altitude at 350", "the Transavia keeps FL170", "the Transavia's there", "KLM12 currently at FL350" (no
  -- copula); unless one of `described_not`
  -- follows ("X is cleared FL200", "X is to climb", "X is required to cross CNR at FL120")
  -- ("Cathay 743 already at FL360 now, please ...": Vietnamese and Thai English's "already" for the copula)
  described = { "is", "are", "keeps", "stays", "remains", "sits", "currently", "already" },
  described_not = { "cleared", "to", "instructed", "told", "requested", "asked", "now", "going", "gonna", "climbing",
                    "descending", "turning", "both", "also", "required", "obliged" },
  -- an aircraft named as the object of one of these is described too, its clause to the next punctuation: "climb
  -- FL130, I've got the Tomjet above at one seven zero", "we've got the KLM at FL170" (G:described)
  described_object = { "got" },
  -- (nor after one of these: "once EZY45 is at 250 knots", "log where AFR1023 is")
  described_after = { "once", "when", "if", "until", "after", "before", "where", "whether", "unless", "while" },
  -- a word between the copula and what the aircraft are doing, read past ("KLM12 and EZY45 are both at FL350")
  described_quantifiers = { "both", "all" },
  -- words after "not" that make it add, not negate: "use vertical speed as well, not just heading and speed" keeps
  -- what follows and adds the rest (G:additive_not)
  additive_not = { "just", "only", "merely", "simply", "solely" },
  -- words after which a clause is a new instruction
  then_words = { "then" },
  -- words that, as "then" does, open what follows a limit "until" a place ("maintain 250 knots till KAMOL,
  -- thereafter 220": from KAMOL; G:until_then)
  until_then_words = { "thereafter" },
  -- words after which a "+" typed before the number is its sign ("vs +1500"): a climb
  -- a step of a study session named after "for" with no determiner ("freeze sim for debrief"): a purpose
  session_steps = { debrief = true, debriefing = true, briefing = true, discussion = true, lunch = true,
                    coffee = true, analysis = true, questionnaire = true, questionnaires = true },
  -- nouns after a verb that make it a phase of the flight named in a remark ("for the cruise segment") (set)
  phase_nouns = { segment = true, phase = true, portion = true, leg = true, part = true, section = true },
  -- a value's name on the flight deck's selector panel, and the word that says it is selected ("HDG SEL")
  selector_names = { hdg = true, heading = true, spd = true, speed = true, alt = true, altitude = true, vs = true,
                     ["v/s"] = true, mach = true, fpa = true },
  selector_words = { sel = true, select = true, selected = true },
  signed_rate_words = { vs = true, ["v/s"] = true, roc = true, rate = true, vspd = true },
  -- a value's name that ends a request straight after "then", "and" or a comma ("climb fl300 then fl"):
  -- the request was cut off before the value, asked
  value_names = { "fl", "level", "altitude", "alt", "heading", "hdg", "speed", "spd", "mach", "vs", "rate" },
  correction = { "correction", "disregard", "negative" },
  -- pronouns that open the reason an instruction is taken back, said after the correction ("insert SINCA... no
  -- wait, it's already there, add BURNY before CANUK": G:taken_back)
  -- the words after which a waypoint condition names the place reached ("when the BA gets to Biggin", "once it
  -- is over Pole Hill", "when you reach Glasgow VOR")
  reached_place_words = { "to", "at", "over", "pass", "passes", "passing", "reach", "reaches", "hit", "hits", "cross",
                    "crosses", "overflies" },
  -- the first words of a remark that judges what the speaker said ("that was wrong", "I got it mixed up", "my
  -- mistake": G:dangling_correction)
  self_correction_judges = { "that", "that's", "this", "i", "i've", "i'd", "my", "it" },
  -- said after a value taken back by a self-correction and said again, the judgement that opens the reason it is
  -- taken back ("2.5 NM, sorry, 2.5 is too small, please use 4 NM": grammar.lua G:ruled_out_reason_end)
  ruled_out_verbs = { "is", "was", "would", "will", "seems", "looks" },
  -- phrases that keep an aircraft from what they are said before ("avoid FL300", "stay clear of FL300") or take it
  -- back ("forget about the climb to FL300", "disregard the climb to FL300", "hold off on the climb"), and the words
  -- that may stand between them and it (`between`): said before an instruction word or a value that a command
  -- carries, with no instruction said before them that they could correct, they are asked (grammar.lua
  -- G:instruction_withheld)
  kept_from = { phrases = { "avoid", "forget", "forget about", "ignore", "disregard", "belay", "scrap", "never mind",
                              "nevermind", "nvm", "stay away from", "keep away from", "stay clear of", "keep clear of",
                              "hold off", "hold off on", "refrain from" },
                  between = { "about", "on", "the", "that", "this", "your", "its", "his", "her", "their", "any", "of",
                              "from", "with", "a", "an" } },
  -- a value judged after it is said ("speed 250, sorry, 250 is too fast", "..., no, that's way too high"): "too",
  -- then one of `too`; the words that may stand between the subject and "too" (`between`); the subjects that judge
  -- the value said before only straight after a marker of lexicon.self_correction (`pronouns`; the value itself
  -- said again judges it anywhere): grammar.lua G:value_rejected
  judged_values = { too = { "fast", "slow", "high", "low", "much", "little", "big", "small", "far", "close", "steep",
                           "early", "late", "quick", "sharp", "tight", "wide", "large", "short", "long" },
                   between = { "is", "was", "would", "will", "be", "seems", "looks", "sounds", "'s", "way", "far", "much",
                               "a", "bit", "little", "slightly", "just", "rather", "quite", "definitely", "probably",
                               "really", "still", "maybe", "kind", "of", "i", "think" },
                   pronouns = { "that", "that's", "thats", "this", "it", "it's", "its" } },
  -- words that open a condition said first after a self-correction's run ("descend FL210, sorry, after EPVOK
  -- descend FL200": the instruction after the condition takes the place of the one before the run; grammar.lua
  -- G:corrected_condition)
  self_correction_condition_openers = { "after", "at", "over", "overhead", "passing", "reaching", "when", "once",
                                        "upon" },
  self_correction_reason_openers = { "it's", "that's", "its", "it", "that", "he's", "she's", "they're" },
  -- who speaks, said as a label before the request ("instructor: KLM101 turn right", "instructor here:
  -- create ...", "sim op: ..."): the label is no part of the request
  speaker_roles = { "instructor", "controller", "atc", "trainer", "supervisor", "examiner", "student", "trainee",
                    "colleague", "colleagues" },
  -- more roles read only as such a label, no word of a request ("the pilots' aircraft" is still asked about)
  label_roles = { "operator", "op", "sim", "simulator", "sup", "pilot", "pseudopilot", "pseudo", "researcher", "experimenter",
                  "ai", "teammate", "assistant", "engineer",
                  -- the same roles in the speaker's language ("istruttore: ...", "supervisore: ...", "piloto: ...",
                  -- "Ausbilder: ...", "ekpaideftis: ..."): Italian, Spanish, Portuguese, French, German, Dutch, Greek
                  "istruttore", "istruttrice", "supervisore", "pilota", "operatore", "controllore", "instructora",
                  "piloto", "operador", "controlador", "instrutor", "instrutora", "instructeur", "instructrice",
                  "superviseur", "pilote", "operateur", "controleur", "ausbilder", "ausbilderin", "fluglotse",
                  "lotse", "pilotin", "betreiber", "piloot", "ekpaideftis", "epoptis", "pilotos", "elegktis" },
  -- a label a speaker puts before a question of their own ("Quick ask: what's the look-ahead set to?", "quick sanity
  -- check, what resolution method are we running?", "quick one: is United 12 climbing?"): one of these phrases,
  -- then a colon, comma or dash, then a word of echo_question_openers; the label is no part of the request
  -- a machine-learning engineer's label before a request of a training run ("obs check: what's X doing",
  -- "warmup, ff 2 min", "new rollout: seed 11, 8 acft"): one of these phrases, then a colon, comma or dash, then
  -- the request; the label is no part of it
  ml_labels = { "obs check", "obs", "observation check", "obs sanity check", "warmup", "warm-up", "warm up",
                "rollout", "new rollout", "next rollout", "new episode", "next episode", "eval rollout",
                "eval run", "new eval", "debug", "debug run", "ablation", "training run", "new training run" },
  question_labels = { "quick ask", "quick question", "quick one", "quick check", "quick sanity check", "sanity check",
                      "one question", "question" },
  -- a meeting's words that turn to another aircraft before what is said about it ("Can we circle back to the
  -- Delta? I'd like it at 250 knots", "let's move on to the United, ..."): up to two words of `leads`, a verb of
  -- `verbs`, a word of `particles`, "to", then "the" and at most three words ending in a mark, with more said after
  -- it; all but "the ..." is dropped, which then names the aircraft as "the Delta, ..." does
  topic_shift = { leads = { "can", "could", "we", "let's", "lets", "so", "now", "ok", "okay", "alright" },
                  verbs = { "circle", "circling", "come", "coming", "go", "going", "get", "getting", "move", "moving",
                            "jump", "jumping", "switch", "switching" },
                  particles = { "back", "on", "over" } },
  -- what a note before a colon is of, besides a role ("exercise note: freeze the simulation"): a label
  note_owners = { "exercise", "scenario", "session", "trial", "run" },
  -- labels of two words that open a line without a colon, as speech recognition writes them ("sim op
  -- delete speedbird one one"): dropped when a request follows
  bare_labels = { "sim op", "sim operator", "simulator operator", "pseudo pilot", "sim pilot" },
  -- the simulator of a station, named after the station's one or two words opening the request before a
  -- comma, colon or dash ("Chicago sim, ...", "N90 sim - ..."): the addressee (G:station_sim; "simulator"
  -- is read as "simulation")
  station_sims = { "sim", "simulation" },
  -- a second speaker's label and assent after the request ("student: ity2011 climb fl150? engineer: yes do
  -- it"): the request stands as said; any other word after such a label leaves the line as typed
  assent = { "yes", "yeah", "yep", "ok", "okay", "sure", "do", "it", "go", "ahead", "fine", "approved",
             "affirm", "correct", "please", "that", "right", "send" },
  -- of those, the machine teammate a controller talks to: it opens a line as its addressee even without a comma
  -- ("AI what's the Virgin's altitude?", "hey teammate descend ..."); a greeting of `greetings` may come first
  -- ("ok AI, ...", "hey teammate: ..."); `greeted`: names of the voice assistant a line is dictated to, its
  -- addressee only after a greeting and before a word ("hey squawk united 452 ...", "ok computer ..."), so
  -- "squawk 4721" and "squawk ident" stay transponder codes
  -- punctuation dictated as words to a voice assistant ("descend 9000 comma reduce 250 period", "where is
  -- UAL1 question mark", "... new line AAL1187 climb ..."): `said` (its words apart, in lower case, after
  -- another word) is `mark`, except before the word `not_before` ("a period of ten minutes")
  -- words after which a speed's digits said in groups ("reduce to 2 5 0", "speed 2 40") are one speed
  speed_split = { speed = true, reduce = true, slow = true, increase = true, accelerate = true },
  dictated_punctuation = { { said = "comma", mark = "," }, { said = "period", mark = ".", not_before = "of" },
    { said = "full stop", mark = "." }, { said = "question mark", mark = "?" }, { said = "new line", mark = "." },
    { said = "new paragraph", mark = "." } },
  -- a term of address to the listener (the simulation, its operator) opening or closing a request, as Turkish
  -- speakers say in English ("Dear system, ...", "..., hocam?", "my friend, ...", "hey simulator, ..."): a word of
  -- `openers` and a word of its list, or a word of `alone`, at the start before a comma, colon or word, or at the
  -- end after a comma or word and before the final mark. No word here is an instruction, callsign or fix word.
  listener_address = { openers = { dear = { "system", "simulator", "sim", "computer", "squawk", "assistant",
                                            "friend", "friends", "colleague", "colleagues", "operator", "machine",
                                            "program", "software", "translator", "ai",
                                            -- a letter's salutation to the people at the scope ("Dear sir, ...")
                                            "sir", "madam", "controller", "controllers", "all", "team", "pilot",
                                            "pilots" },
                                   my = { "friend", "friends", "dear" },
                                   hey = { "system", "simulator", "friend", "friends", "assistant", "machine" },
                                   hello = { "system", "simulator", "computer", "friend", "friends", "assistant" } },
                       -- Turkish "my teacher", the respectful address to anyone ("hocam", "hocacım")
                       alone = { "hocam", "hocacim", "hocacigim" },
                       -- a courtesy said before the term of address, lower case ("Excuse me dear system, ...")
                       led = { "excuse me", "pardon me", "please", "with your permission" } },
  addressed_roles = { names = { "ai", "teammate", "assistant" }, greeted = { "squawk", "computer" },
                      greetings = { "ok", "okay", "hey", "hi", "right", "alright", "so" } },
  -- a speaker correcting the value just said ("270, no wait, 260", "180 ... actually make that 170",
  -- "heading 090, oh no, right heading 200"): a run of `words` between a value and the next value,
  -- direction or value noun, holding one of `markers` (a word, or two in a row: "make" alone is no
  -- correction, "KL204, make one orbit"), is read as "correction"
  -- (radiotelephony's "FL260, I say again 260" repeats the value: read as a correction, it keeps it)
  -- (typed: "210 hmm no 200")
  -- the words that may follow "cancel that" said straight after a value, with no comma, where it takes the value
  -- back ("climb FL330 cancel that maintain FL310"): an instruction's verb or a level's first word
  cancel_correction_next = { "maintain", "climb", "descend", "reduce", "increase", "turn", "fly", "expedite", "slow",
                             "fl", "flight", "mach" },
  -- the words of an instruction that a speaker may break off ("direct...", "climb-") and replace, after a hesitation,
  -- by another of them (G.abandoned_instruction_words)
  abandoned_instruction_words = { "direct", "heading", "climb", "descend", "speed", "level", "altitude" },
  -- the words that open a heading flown instead of a direct-to taken back ("cancel the direct, fly heading 120":
  -- G.cancelled_direct)
  direct_cancelled_by = { "fly", "turn", "heading", "hdg", "continue", "maintain", "resume" },
  -- the verbs that take back what was just said, before "that" ("cancel that", "belay that": G.cancel_corrections),
  -- and the correction words (lexicon.correction) that take it back when an instruction of another kind with no
  -- value is said in its place ("turn left heading 360, disregard, continue on your route": the heading dropped,
  -- G:parse; one with a value, "climb FL300, cancel that, reduce 250 knots", is asked, instead or as well)
  cancel_verbs = { "cancel", "belay" },
  correction_taking_back = { "disregard" },
  -- a coordinate's axis ("lat", "lon") by the label said before its number ("latitude 41.4 north") and by its
  -- hemisphere's word or letter (grammar.lua G.spoken_coordinates)
  -- (a hemisphere typed as its initial in capitals, "41.4 N", is that word's)
  -- the nouns of a value that a number written with a decimal comma may follow ("the horizontal resolution factor
  -- to 1,1"; grammar.lua G.decimal_comma)
  decimal_comma_after = { "factor" },
  -- the units of a distance, which takes a decimal, that a number written with a decimal comma may precede ("a
  -- zone of 4,5 NM"; grammar.lua G.decimal_comma)
  decimal_comma_units = { "nm", "nmi", "miles", "mile", "nautical", "km", "dme" },
  coordinate_axes = { labels = { latitude = "lat", longitude = "lon" },
                      hemispheres = { north = "lat", south = "lat", east = "lon", west = "lon" } },
  -- "I said FL260 but is FL270", "I said heading 200, but it's 210", "I said 250 knots but I meant 240": the words
  -- of the values named with "I said" and after "but" (their units and nouns), and the phrases after "but" that
  -- restate (grammar.lua G.said_but)
  said_but = { value_words = { fl = true, flight = true, level = true, heading = true, speed = true, mach = true,
                               altitude = true, knots = true, feet = true, ft = true, kts = true, degrees = true,
                               left = true, right = true },
               restating = { "i meant", "i mean", "it is", "it's", "it was", "it should be", "should be", "is",
                             "was", "meant" } },
  self_correction = { words = { "oh", "ay", "no", "wait", "sorry", "actually", "make", "that", "i", "mean", "meant", "uh", "um",
                                "er", "eh", "ah", "say", "again", "scratch", "corr", "hmm", "typo", "never", "mind", "nevermind", "nvm",
                                "forget", "belay", "better", "rather", "amend",
                                -- a South African's interjections before the marker ("FL210, ag sorry, FL230",
                                -- "heading 200, shame sorry, 210", "eish, no, 080"; a Singaporean's "aiyah sorry")
                                "ag", "shame", "eish", "aiyah", "aiya", "aiyoh", "aiyo" },
                      -- words of an apology ("I am sorry", "I'm sorry") also part of a run between two values
                      -- (grammar.lua self_corrections: "flight level 110, I am sorry, flight level 100")
                      -- ("heading 270, actually no, let's make that 280": "let's" before "make that" belongs to the
                      -- run; "fl250 nein fl270", "kurs 300.. ne 310": German "nein", "ne" (no) are its markers; the
                      -- Filipino "po" of respect after the apology, "sorry po"; a Spanish speaker's "bueno", its marker)
                      value_words = { "am", "i'm", "let's", "lets", "let", "nein", "ne", "po", "bueno" },
                      markers = { "no", "wait", "sorry", "actually", "make that", "mean", "meant", "say again", "scratch",
                                  "corr", "never mind", "nevermind", "nvm", "forget that", "belay", "nein", "ne",
                                  -- (a Spanish speaker's "well" between two values: "FL120, bueno, FL140"; a US
                                  -- controller's "amend" between two values: "one six thousand, amend, one four thousand")
                                  "bueno", "amend" },
                      -- the markers that, closing the request, take back what came before with nothing said
                      -- in its place ("turn left 20, sorry": asked); "I mean" closing it points back at what
                      -- it follows ("the Wideroe, I mean"), "actually" closing it is "in fact" ("going to
                      -- Valencia actually"), "from scratch" is no correction
                      closing = { "no", "wait", "sorry", "make that", "say again", "corr", "never mind", "nevermind", "nvm",
                                  "forget that", "scratch that", "belay that" },
                      after = { "fl", "flight", "level", "heading", "left", "right", "speed", "mach", "altitude" },
                      -- the first words of the markers that take back what they follow in words ("never mind",
                      -- "forget that", "scratch that"): before an instruction's word, no value is corrected
                      dropping = { "never", "nevermind", "nvm", "forget", "scratch", "belay" },
                      -- said after a marker and ending its clause, what was said before is left as it was: taken
                      -- back as "forget that" takes it back ("detection off. Ah no, leave it. ..." keeps detection)
                      left_as_is = { "leave it as it is", "leave it as is", "leave it like that", "leave it alone",
                                     "leave it on", "leave it", "leave that one", "leave this one", "leave that",
                                     "keep it as it is", "keep it as is", "keep that one" },
                      -- said between "leave"/"keep" and a noun of just_the ("leave its heading"): the instruction
                      -- of that kind said before the marker is left as it was (grammar.lua G:left_as_is_end)
                      left_named = { "its", "the", "his", "her", "their" },
                      -- "... actually no, just the descent": after a self-correction, "just"/"only" and one of these
                      -- names the instructions said before it that stand (by the command they issued)
                      only = { "just", "only" },
                      -- an apology closing a value ruled out ("fl200 not 180 sorry"): the value before stands
                      apology = { "sorry", "apologies", "oops", "soz" },
                      -- said after a marker, an apology or a hesitation and closing the request, the speaker
                      -- stops to think or drops what was said with nothing in its place ("climb FL280... no wait,
                      -- let's see", "speed 250, sorry, let me think", "..., no, forget it"): taken back, asked
                      -- (grammar.lua G:withheld_start)
                      withheld = { "let's see", "let us see", "let me see", "let me think", "let me check",
                                   "let me check something", "let me think about it", "let me double-check",
                                   "let me double check", "hold on", "hang on", "hold that thought", "stand by",
                                   "standby", "bear with me", "one moment", "a moment", "one second", "a second",
                                   "one sec", "a sec", "just a moment", "just a second", "just a sec",
                                   "wait a second", "wait a moment", "wait a minute", "wait a sec",
                                   "give me a second", "give me a moment", "give me a sec", "forget it",
                                   "scrap that", "ignore that", "cancel that", "not that", "not yet",
                                   "i'm not sure", "not sure",
                                   -- ("descend to level 280, no, stop, keep": what is kept is unsaid)
                                   "keep", "keep it",
                                   -- (the speaker searching his memory for the value: "descend FL100, no wait,
                                   -- what level was it again")
                                   "what was it", "what was it again", "what was that again",
                                   "what level was it", "what level was it again", "which level was it",
                                   "which level was it again", "what heading was it", "what heading was it again",
                                   "what speed was it", "what speed was it again", "which speed was it",
                                   "which speed was it again", "which heading was it", "which heading was it again",
                                   "i forgot", "i forget",
                                   "i don't remember", "i do not remember" },
                      -- formal apologies, and a slip's exclamation as typed ("oops", "ops", "opps", "oups"),
                      -- read as "sorry" (a marker) wherever they are said ("Mach 0.80 -- pardon me, Mach 0.78",
                      -- "the United -- no, forgive me, the Southwest", "Gol 12, ops, Gol 21, descend ...")
                      -- the speaker admitting a slip, set off by a mark and followed by more of the request
                      -- ("speed 250 knots... sorry, I mistook, 230 knots", "FL110, my mistake, FL100"): read as
                      -- "sorry" (a marker); closing the request or running on ("I made a mistake when creating
                      -- it") they are no marker (judged)
                      admitted = { "i mistook", "i made a mistake", "i made an error", "my mistake", "my error",
                                   "i was mistaken", "i was wrong",
                                   -- (the same admitted in Vietnamese and Thai English, no tense or article:
                                   -- "sorry I mistake, 300 not 310")
                                   "i mistake", "i make mistake", "i make a mistake", "i made mistake",
                                   -- (the slip named as what was said: "FL340, sorry, I said wrong, FL320",
                                   -- "300... ah sorry, it was wrong, 260 is correct")
                                   "i said wrong", "i said it wrong", "i said that wrong", "it was wrong",
                                   "that was wrong", "this was wrong" },
                      -- a unit named after a marker, "better" or "rather" and "in", then a mark and a value in
                      -- that unit ("Mach 0.7, no, better in knots please, 240 knots"): the unit phrase is dropped
                      -- (grammar.lua G.unit_restated); each unit as said, then the Lua patterns of its value
                      restated_units = {
                        { said = { "knots", "knot", "kts", "kt" }, value = { "^%d+%s*knots?%f[%A]", "^%d+%s*kts?%f[%A]" } },
                        { said = { "mach" }, value = { "^mach%s*[%d%.]" } },
                        { said = { "feet", "ft" }, value = { "^%d[%d,]*%s*feet%f[%A]", "^%d[%d,]*%s*ft%f[%A]" } },
                        { said = { "flight levels", "flight level", "fl" },
                          value = { "^fl%s*%d", "^flight%s+level%s+%d" } } },
                      -- said after a marker, before the value said in place of the one taken back ("I am sorry,
                      -- it is 260"): part of the correction's run
                      -- ("sorry I want to say 300", "no, I wanted to say FL320", "sorry, I meant to say 300": the
                      -- value the speaker means said after "to say", as an East African speaker says it)
                      -- ("no, I wanted FL300", "sorry, I want 260": the value wanted said straight after "I want"
                      -- or "I wanted", as a Hungarian, Romanian or Ukrainian speaker says it; last, so that the
                      -- longer phrases match first)
                      restated = { "it is", "it's", "it should be", "want to say", "wanted to say", "wish to say",
                                   "to say", "wanted", "want" },
                      -- modals said after the addressee restated in a correction ("sorry, Turkish 876 should climb
                      -- to FL320": G.restated_addressee)
                      restated_modals = { "should", "must", "shall", "will", "has to", "needs to", "is to" },
                      formal_apology = { "i beg your pardon", "beg your pardon", "pardon me", "forgive me",
                                         "excuse me", "my apologies", "oops", "ops", "opps", "oups", "whoops",
                                         "woops", "oopsie", "whoopsie",
                                         -- (French "pardon" said alone in English: "climb FL360, pardon,
                                         -- FL370", "reduce, pardon, increase 300 knots")
                                         "pardon",
                                         -- (an apology for the requests said together, "Sorry for many requests
                                         -- at once.": "at once" in it is no timing)
                                         "sorry for many requests at once", "sorry for so many requests at once",
                                         "sorry for the many requests at once", "sorry for all the requests at once",
                                         "sorry for many instructions at once",
                                         "sorry for so many instructions at once" },
                      -- an apology said as a sentence or clause of its own, set off by marks on both sides and
                      -- followed by more of the request ("descend FL240. Sorry about that. After TOLPA descend
                      -- FL230", "..., I apologise, ..."): read as "sorry" (a marker) there only; said elsewhere ("I
                      -- apologize for the delay", "apologies for the many requests") it is no marker
                      apology_sentence = { "sorry about that", "sorry about this", "sorry for that", "sorry for this",
                                           "so sorry", "very sorry", "really sorry", "terribly sorry",
                                           "i apologize", "i apologise", "i do apologize", "i do apologise",
                                           "apologies", "many apologies" },
                      -- words that describe the aircraft said in place of one taken back ("American 100 -- no,
                      -- the second aircraft, United 200"; aircraft nouns too): part of the correction's run
                      described = { "the", "a", "an", "first", "second", "third", "fourth", "other" },
                      -- words of a remark that judges what was said ("that was wrong", "I got it mixed up", "my
                      -- mistake"): closing the request, such a remark takes the instruction back, asked
                      judged = { "wrong", "mistake", "mistaken", "incorrect", "misspoke", "misspoken", "error",
                                 "typo", "mixed", "muddled", "backwards", "meant", "messed" },
                      -- a verb of setting before the instruction said in place of the one taken back ("half
                      -- height one thousand... no, set zone half height to five hundred feet")
                      setting = { "set", "put", "change", "reset" },
                      -- the nouns of just_the that say the kind alone after "just"/"only", no "the", closing the
                      -- request ("..., no forget it, only speed")
                      just_bare = { "speed", "heading", "altitude", "level", "descent", "mach" },
                      just_the = { ALT = { "descent", "descend", "climb", "altitude", "level", "levels", "alt" },
                                   HDG = { "turn", "heading", "vector", "hdg" },
                                   SPD = { "speed", "slowdown", "mach", "spd" },
                                   DIRECT = { "direct", "directs", "dct" }, VS = { "rate", "vs" } } },
  -- the simulation itself, not an aircraft
  -- (an episode: one run of a learning environment; "env", "environment": the environment itself)
  -- (a replay: recorded traffic run again, in an analyst's words: "pause the replay", "remove X from the replay")
  -- (a serial: one run of a military exercise, "resume the serial")
  -- (a game: the simulation in a newcomer's words, "pause the game", "make the game go 10x")
  sim = { "simulation", "sim", "simulator", "time", "exercise", "clock", "episode", "env", "environment", "replay",
          "playback", "serial", "game" },
  -- (an agent: an aircraft, in a learning environment's words)
  -- what an aircraft has, named after its owner's possessive typed without an apostrophe ("ual22s route":
  -- grammar.lua G.possessive_ids)
  possessed_by_aircraft = { "route", "rte", "trail", "trails", "altitude", "alt", "level", "heading", "hdg", "speed",
    "spd", "position", "pos", "destination", "dest", "origin", "waypoints", "wpts", "flight", "callsign", "type",
    "vertical", "mach", "state", "status", "track", "plan", "lnav", "vnav" },
  aircraft_nouns = { "aircraft", "plane", "airplane", "flight", "agent",
      -- (an aircraft as its pilot, in an Irish or British speaker's word: "the lowest fella there")
      "fella", "fellow" },
  -- words that compare the aircraft flying by their state, said after "the" (G:described_refs): the field of
  -- the aircraft's state compared and +1 for the most of it, -1 for the least; how near two values are for the
  -- words to tell those aircraft apart no more (ft, kt); the nouns naming every aircraft flying as the group
  -- compared ("the slowest of the aircraft", "the faster of the two planes")
  compared_measures = { highest = { "alt_ft", 1 }, higher = { "alt_ft", 1 }, lowest = { "alt_ft", -1 },
    lower = { "alt_ft", -1 }, fastest = { "cas_kt", 1 }, faster = { "cas_kt", 1 }, quickest = { "cas_kt", 1 },
    quicker = { "cas_kt", 1 }, slowest = { "cas_kt", -1 }, slower = { "cas_kt", -1 },
    -- (where it is: "the easternmost aircraft", "the northernmost one"; the shorter forms, "the eastmost one")
    northernmost = { "lat", 1 }, southernmost = { "lat", -1 }, easternmost = { "lon", 1 }, westernmost = { "lon", -1 },
    northmost = { "lat", 1 }, southmost = { "lat", -1 }, eastmost = { "lon", 1 }, westmost = { "lon", -1 } },
  -- (lat, lon: degrees, about a mile)
  compared_margin = { alt_ft = 100, cas_kt = 5, lat = 0.02, lon = 0.02 },
  -- the plain words that describe one aircraft by its state before "one" or an aircraft noun ("the slow one", "the
  -- high aircraft"), read as the superlative, and how far the aircraft picked must lead the next for the plain
  -- word to fit it alone (ft, kt: at least this)
  compared_plain = { slow = { "cas_kt", -1 }, fast = { "cas_kt", 1 }, low = { "alt_ft", -1 }, high = { "alt_ft", 1 } },
  compared_plain_margin = { alt_ft = 2000, cas_kt = 20 },
  -- [deg] two aircraft fly head-on ("the two head-on ones") when their headings lie within this of opposite and
  -- each heads within this of the bearing to the other, and fly less than head_on_ft [ft] apart in level
  head_on_deg = 20, head_on_ft = 1000,
  -- where an aircraft is on the north-up screen or map (handlers: position_refs; accounted for only where that
  -- reads them, so "at the top of the hour" stays asked): a side's words and its direction {east, north} (two make
  -- a corner: "the top left"); the words of the traffic's centre; the nouns a side may end with ("the top left
  -- corner") and the displays it may be "of" ("of the screen"); the words opening a side said after the aircraft
  -- ("the one at the top", "the plane up in the top left", "the Air Canada down in the south-west", "near the top
  -- left"), and those before it that change nothing ("very", "far"); the words of an aircraft said by the place
  -- it is next to ("the one next to Pearson", "right by LINNG"); the airport of an exercise said by a noun
  -- ("north-east of the field")
  screen_position = {
    sides = { top = { 0, 1 }, upper = { 0, 1 }, bottom = { 0, -1 }, lower = { 0, -1 }, left = { -1, 0 },
              right = { 1, 0 } },
    middle = { "middle", "centre", "center" },
    nouns = { "corner", "side", "edge", "end", "part", "area", "bit" },
    names = { "screen", "scope", "map", "display", "radar", "picture" },
    at = { "at", "on", "in", "near", "towards", "toward" },
    leaning = { "up", "down", "over", "out", "way", "right", "just", "very", "far", "sitting", "that's", "currently" },
    near = { "near", "beside", "by" },
    near_to = { "next", "close", "closest", "nearest" },
    fields = { "field", "airport", "aerodrome", "airfield" } },
  -- how clearly the aircraft picked must stand out of the others that fit: its lead over the runner-up along the
  -- side (or, in the middle or near a place, its distance's lead), at least this fraction of the traffic's
  -- spread along that side and at least position_lead_nm [NM]; one near a place lies within position_near_nm
  -- [NM] (or that fraction of the traffic's spread) of it
  position_lead = 0.15, position_lead_nm = 3, position_near_nm = 10,
  -- an aircraft described by when it was created ("the aircraft I created last", "the first one we added", "the
  -- one created most recently"): the verbs (as the lexer reads them: "created" is "create"), the people who
  -- create, and the words of order (true: the latest)
  created_verbs = { "create", "created", "make", "made", "add", "added", "spawn", "spawned", "generate", "put", "place",
      "enter" },
  created_by = { "i", "we", "you", "i've", "we've", "you've" },
  -- the adverbs before "created" that say the aircraft was just created ("the before created aircraft", German
  -- "das vorher erstellte"; "the newly created one"; handlers' created_just_said)
  created_just = { "before", "just", "newly", "previously", "recently", "earlier" },
  created_order = { last = true, latest = true, recently = true, first = false, earliest = false },
  -- an aircraft described by its airline's country after "the" ("the German one", "the Danish ATR", "could the
  -- Irish one descend", "the Chilean Dreamliner"; handlers' m:nationality_refs): the adjective and the ICAO
  -- designators of that country's airlines. An airline of several countries is under each ("SAS": Danish, Swedish
  -- and Norwegian), so that a description both could meet is asked. Only read when every aircraft flying has a
  -- country here (or in registration_countries): an airline missing from the table could be the one meant.
  airline_countries = {
    british = { "BAW", "SHT", "CFE", "EFW", "EZY", "EXS", "TOM", "VIR", "LOG", "RUK", "WUK", "AUR", "DHK", "BEE" },
    irish = { "EIN", "RYR", "EAI", "BCY", "IRL", "ABR" },
    german = { "DLH", "EWG", "CFG", "TUI", "GEC", "CLH", "BCS", "GWI", "OCN", "GAF" },
    dutch = { "KLM", "TRA", "KLC", "MPH", "CND", "TFL", "NAF" },
    danish = { "DTR", "SAS", "DAF" },
    swedish = { "SAS", "SWN", "NSZ", "BRX", "SVF" },
    norwegian = { "SAS", "NAX", "NSZ", "NOZ", "WIF" },
    finnish = { "FIN" },
    icelandic = { "ICE", "FPY", "ABD" },
    french = { "AFR", "HOP", "TVF", "FBU", "CRL", "FAF" },
    spanish = { "IBE", "VLG", "AEA", "IBS", "ANE", "VOE", "EVE", "IBB" },
    italian = { "ITY", "AZA", "DLA", "NOS", "IAM" },
    portuguese = { "TAP", "RZO", "AFP" },
    belgian = { "BEL", "JAF", "BAF" },
    polish = { "LOT", "ENT", "RYS", "PLF" },
    hungarian = { "WZZ" },
    czech = { "CSA", "TVS", "CEF" },
    latvian = { "BTI" },
    greek = { "AEE", "OAL", "HAF" },
    chilean = { "LAN", "SKU", "JAT" },
    brazilian = { "TAM", "GLO", "AZU", "PTB" },
    canadian = { "ACA", "WJA", "JZA", "ROU", "TSC", "POE", "SWG", "WEN", "FLE" },
    mexican = { "AMX", "VOI", "VIV" },
    japanese = { "JAL", "ANA", "APJ", "SNJ", "ADO", "JTA", "SKY", "IBX", "FDA" },
    australian = { "QFA", "VOZ", "JST", "QLK" },
    vietnamese = { "HVN", "VJC", "BAV" },
    russian = { "AFL", "SBI", "SDM", "PBD", "UTA" },
  },
  -- the nationality marks that open registrations flown as callsigns (PH-ABC: Dutch; N248DM: American, a digit
  -- after the N), for m:nationality_refs
  registration_countries = { PH = "dutch", D = "german", G = "british", EI = "irish", OY = "danish", SE = "swedish",
                             LN = "norwegian", OH = "finnish", TF = "icelandic", F = "french", EC = "spanish",
                             I = "italian", CS = "portuguese", OO = "belgian", SP = "polish", HA = "hungarian",
                             OK = "czech", YL = "latvian", SX = "greek", CC = "chilean", PP = "brazilian",
                             PR = "brazilian", PT = "brazilian", C = "canadian", XA = "mexican", JA = "japanese",
                             VH = "australian", VN = "vietnamese", RA = "russian", N = "american" },
  -- what an aircraft carries, said after "the" to name it ("the cargo aircraft", "the freighter"): the traffic
  -- tells no such thing, so the words are asked about (an airline or type said with them names the aircraft:
  -- "the DHL cargo plane")
  carried_described = { "cargo", "freighter", "freighters", "freight", "passenger", "charter" },
  -- [deg] how far an aircraft's heading may lie from a cardinal point that describes it ("the one heading north":
  -- less than this on either side; 45 keeps an aircraft on 135 out of both "south" and "east"); half of it from
  -- an intercardinal point ("south-west"), a quarter from one between them ("north-north-east")
  bearing_margin = 45,
  group_nouns = { "aircraft", "planes", "airplanes", "flights", "jets", "ones", "them", "all", "fellas" },
  -- words that describe an aircraft before "from" and its airline ("the regional jet from Republic")
  aircraft_described = { "jet", "jets", "regional", "airliner", "one", "small", "big", "heavy", "little", "widebody",
      "narrowbody", "turboprop", "prop", "aeroplane" },
  -- an abbreviation's words said out, read as the abbreviation ("resume navigation after passing the closest
  -- point of approach" is "... the CPA")
  -- ("... when they are past the closest point": the CPA passed, said without "of approach")
  spelled_out = { ["closest point of approach"] = "CPA", ["own ship"] = "ownship",
                  ["past the closest point"] = "past the CPA", ["past their closest point"] = "past their CPA",
                  ["passed the closest point"] = "passed the CPA", ["passing the closest point"] = "passing the CPA" },
  -- the roles of a conflict study (handlers: role_refs): "subject aircraft is X", "intruder X", "X is the
  -- intruder" declare which aircraft "the intruder" / "the subject aircraft" means later in the request
  role_nouns = { "intruder", "subject", "ownship", "ego", "agent" },
  -- roles mentioned without "the" ("give ownship heading 240")
  role_bare = { "ownship", "ego", "agent" },
  -- words of a sentence that only declares roles ("Subject X, intruder Y, both FL310."; "The subject aircraft
  -- X and the intruder Y are converging;"): with them and values, the sentence is context, never an instruction
  role_described = { "both", "each", "at", "are", "is", "and", "the", "same", "level", "levels", "flying",
                     "converging", "diverging", "crossing", "opposite", "co-altitude", "in", "on", "aircraft" },
  -- aircraft counted with no callsign ("spawn 3 aircraft", "create 20 agents"): random traffic (MCRE)
  counted_aircraft = { "aircraft", "planes", "airplanes", "flights", "agents", "jets", "airliners", "aeroplanes" },
  -- aircraft makers' names in the plural ("the two Airbuses")
  maker_plurals = { "airbuses", "boeings", "embraers", "bombardiers", "cessnas", "atrs", "dreamliners", "jumbos" },
  -- imperative verbs that open an instruction of their own after a comma, even after traffic information
  -- words of a hand-off's station and courtesy after "contact" or "monitor" (grammar.lua G.handoff_to_end)
  handoff_words = { "the", "on", "frequency", "freq", "tower", "approach", "director", "radar", "ground", "departure",
                    "control", "centre", "center", "information", "arrival", "decimal", "point", "please", "thank",
                    "thanks", "you" },
  clause_verbs = { "turn", "climb", "descend", "reduce", "increase", "fly", "proceed", "expedite" },
  -- nouns of a vertical speed that, opening the clause after traffic information and its comma with a value after
  -- them, give the rate of the climb or descent said before it (grammar.lua G:not_simulated)
  clause_rates = { "rate", "vertical" },
  -- phrases that pick one aircraft of several named together ("put one of them at FL190", "climb either of them"):
  -- which one is asked (handlers.lua m:acids)
  partitive_selectors = { "one of them", "one of those", "one of these", "one of the two", "one of both",
    "either of them", "either of those", "either of these", "either of the", "either one", "any of them",
    "any one of", "one or the other", "whichever", "the first one", "the second one", "the former", "the latter" },
  -- ordinals that pick one of several aircraft named together when said as a noun of their own ("put the first at
  -- FL190", "the second, climb FL250", "the first of them"): the word after is punctuation, the request's end, an
  -- instruction verb (clause_verbs) or one of `then`; "the first fix", "the second turn" name no aircraft
  ordinal_selectors = { words = { "the first", "the second" },
    next = { "at", "to", "of", "one", "aircraft", "plane", "flight", "jet", "please", "should", "can", "could", "will",
      "needs", "must", "then", "and", "maintain", "go", "stop", "slow", "speed", "heading", "level" } },
  -- instruction verbs, their -ing forms and nouns that "no" said straight before, with no comma between ("PRF441
  -- no descend FL090", "no climbing", "no descent", "no left turn": a turn's side may come between), may refuse
  -- ("do not descend", in English as a second language) as well as take back what came before ("no, descend"):
  -- asked (G:unaccounted)
  -- (nouns said after "no" as often as verbs are left out: "no route", "no crossing traffic")
  refusable_verbs = { "turn", "climb", "descend", "reduce", "increase", "fly", "proceed", "expedite", "maintain",
                      "slow", "accelerate", "decelerate", "go", "direct", "continue", "resume", "join", "intercept",
                      "turning", "climbing", "descending", "reducing", "increasing", "flying", "proceeding",
                      "expediting", "maintaining", "slowing", "accelerating", "decelerating", "continuing",
                      "resuming", "joining", "intercepting", "descent", "turns", "climbs" },
  -- units a fraction said in words is of ("half a mile": 0.5 nm)
  fraction_units = { mile = true, miles = true, nm = true, nmi = true, mi = true },
  -- units typed after a setting's value in a notebook's call form ("spd(250kt)", "vs(-2000fpm)")
  notebook_units = { kt = true, kts = true, knots = true, ft = true, feet = true, fpm = true, deg = true,
                     degs = true, degrees = true },
  -- A script's "%" comment after a value (G.script_comment): each word it may hold and how it is read. unit:
  -- typed after the value; prefix: typed before it ("alt 210 % FL" is FL210, "spd = .78 % mach" Mach .78);
  -- side: the turn's or the rate's direction, typed after the value and its unit. A word of no kind here makes
  -- the comment no unit nor side.
  script_comment_words = {
    ft = { unit = "ft" }, feet = { unit = "ft" }, foot = { unit = "ft" },
    kt = { unit = "kt" }, kts = { unit = "kt" }, knots = { unit = "kt" }, knot = { unit = "kt" },
    fpm = { unit = "fpm" }, ["ft/min"] = { unit = "fpm" },
    m = { unit = "m" }, metres = { unit = "m" }, meters = { unit = "m" }, metre = { unit = "m" }, meter = { unit = "m" },
    nm = { unit = "nm" }, s = { unit = "s" }, sec = { unit = "s" }, secs = { unit = "s" }, seconds = { unit = "s" },
    deg = { unit = "degrees" }, degs = { unit = "degrees" }, degrees = { unit = "degrees" },
    fl = { prefix = "FL" }, mach = { prefix = "mach " },
    r = { side = "right" }, right = { side = "right" }, l = { side = "left" }, left = { side = "left" },
    up = { side = "up" }, climb = { side = "up" }, down = { side = "down" }, descend = { side = "down" },
  },
  -- units that close a number typed with a space before its last three digits ("8 500 m", "12 000 ft")
  thousands_units = { m = true, ft = true, feet = true, foot = true, metres = true, meters = true, metre = true,
                      meter = true },
  waypoint_nouns = { "waypoint", "wpt", "wp", "fix", "waypoints", "fixes", "wpts", "wps" },
  route_nouns = { "route", "plan", "path", "routing", "rte" },
  -- the route's own values named with no value after a route instruction ("follow the route, speeds included",
  -- "resume own navigation, levels too", "..., speed restrictions too": G:values_named_alone): the nouns (plurals
  -- as said; the constraints on them too), the words closing such a clause ("as well" is matched as two words), and
  -- the verbs that fly a route whose values they are
  route_value_nouns = { "speed", "speeds", "level", "levels", "altitude", "altitudes", "height", "heights",
                        "restriction", "restrictions", "constraint", "constraints" },
  route_value_closers = { "included", "too", "also" },
  route_value_verbs = { "follow", "follows", "following", "resume", "resumes", "resuming", "rejoin", "rejoins",
                        "continue", "continues" },
  articles_new = { "a", "an", "new", "second", "another", "more" },
  -- families whose first variant in the data is not the one every writer means by the family's name alone
  -- ("a Boeing 767": B762 in the data, B763 meant; "a United 787": B788 or B789; "a 737", "a Southwest 737":
  -- B737 to some writers, B738 to others, with or without an airline; "an Airbus three thirty": A333 to four
  -- writers, A332 to two, "A330" to four): asked about when an aircraft is created; any other family is its first
  -- variant (757 -> B752, 777 -> B772, A350 -> A359, types.lua), as the writers of every round so far and
  -- BlueSky's own corpus read them (nl2trafscript_dev d001: "a Boeing 777" is B772); a Boeing family is its 7x7
  -- digits, an Airbus one its 3x0 ("330", read only after "A" or "Airbus")
  variant_families = { "737", "767", "787", "220", "330" },
  -- a family's nickname said alone for a new aircraft that every writer reads as one variant ("a 737 MAX", "Boeing
  -- 737 MAX": the MAX 8, four writers of four); any other nickname naming several designators is asked about
  nickname_defaults = { max = "B38M" },
  -- a family whose designators its digits do not spell (handlers_other ask_variant): its name and their pattern
  variant_designators = { ["220"] = { name = "A220", pattern = "^BCS%d$" } },
  all = { "all", "both", "every", "everything" },
  -- direction of a change: +1 words and -1 words
  up = { "climb", "clb", "up", "raise", "increase", "faster", "above", "higher", "accelerate", "climbing",
         "ascend", "rise", "upward", "upwards" },
  down = { "descend", "desc", "down", "drop", "lower", "reduce", "decrease", "slow", "slower", "below", "descent", "sink",
           "descending", "decelerate", "minus", "subtract", "downward", "downwards" },
  -- words that name an aircraft as context, not as the one instructed ("avoid AC02")
  aircraft_context = { "between", "avoid", "avoiding", "conflict", "conflicts", "behind", "follow", "following",
                       "than", "traffic", "meet", "meets", "catch",
                       -- "climb through DLH9CE's level"
                       "through",
                       -- "out of the way of INT1"
                       "way",
                       -- "turn left 20 into the Vueling 1723", "turn towards VLG1723": the traffic turned toward
                       "into", "towards", "toward",
                       -- "vertical separation from RYR7QD": the traffic kept apart from
                       "separation" },
  -- verbs of one aircraft nearing another, said before "on" (or "up on") the other ("KLM12 is creeping up on the
  -- Easy", "closing on EZY45", "gaining on the Ryanair"): the other is the traffic neared, never instructed
  neared_verbs = { "closing", "gaining", "creeping", "catching", "sneaking", "bearing", "coming", "converging", "homing" },
  -- verbs whose "to" names the aircraft that receives what they give ("give FL200 to the Embraer": handlers.lua
  -- m:recipient_to)
  recipient_verbs = { "give", "assign", "issue", "allocate" },
  -- words before an airline said alone ("pointing at the Lufthansa", "too close to the BA", "into the
  -- Austrian's level", "climb through the Lufthansa's level") that make it other traffic, not the aircraft instructed
  airline_context = { "at", "into", "to", "with", "near", "from", "past", "towards", "toward", "except", "but",
                     "through" },
  -- words that open the reason given for an instruction (to the end of its
  -- sentence): aircraft named in it are context, never instructed
  reason = { "because", "since", "cause", "due" },
  -- verbs of the experimenter's purpose after a comma (", we want it crossing ..."): a reason
  purpose_verbs = { "want", "need", "don't", "dont", "wanna" },
  reason_after_so = { "that", "it", "they", "it's", "its", "we", "he", "she", "he's", "she's", "the",
    -- (the class or trainees the instructor shows the traffic to: ", so you can see it turn", "so everyone can see it")
    "you", "you'll", "everyone", "everybody", "they'll" },
  -- the experimenter's check after an instruction, "see" then one of these ("ff 2 min and see if they lose
  -- separation", ", see whether that's enough"): a reason, to the end of its sentence
  see_whether = { "if", "whether" },
  -- asides set apart from a complete instruction (G:commentary; they account for no word): a span after a dash or in brackets,
  -- or a clause after a comma opening with one of `subjects` ("- hard test of the turn model", ", we only
  -- care about the descent phase"); a lead-in before a colon opening with one of `leads` ("For the
  -- vertical test: ..."); what follows one of `labels` and a colon ("reason: lose the overlap with
  -- TOM6RT"). A span holding one of `blocks` (it adds to, repeats or takes back an instruction) is asked
  -- about, and so is one holding a negation or condition unless it opens with `own` (the experimenter's
  -- own doing: "- I want to check the geometry before the conflict starts")
  -- ("turn off trails, too cluttered": a degree word opens a remark too). After `own` and "while"
  -- ("pause the sim while I reset the eye tracker") or in a clause of `own` with one of `later` ("heading
  -- 150 for now, we'll put it back on the route later") the experimenter's own doing is set aside even
  -- with instruction words, never with a value. Before a colon, an aircraft after one of `lead_context`
  -- is other traffic when the request names its own aircraft after the colon ("Add an intruder for
  -- VIR9: DLH9KW A321 at ...")
  -- after "show me", words for the aircraft named shown together ("show me both of them, KLM12 and EIN45", "...,
  -- show me the both of them", "show me them all")
  shown_together = { "both", "of", "them", "the", "and", "all", "two", "pair" },
  aside = { subjects = { "we", "i", "it", "he", "she", "they", "that", "this", "it's", "that's", "we're",
                         "we'll", "we'd", "i'm", "i'll", "i'd", "he's", "she's", "they're", "there's", "too",
                         -- (the instructor's forecast: "he'll clip the danger area otherwise", "it'll be tight")
                         "he'll", "she'll", "it'll", "they'll",
                         -- (the speaker's need, its "I" dropped: "pause pls, need a break")
                         "need",
                         "participant", "participants", "experimenter", "researcher" },
          own = { "we", "i", "we're", "we'll", "we'd", "i'm", "i'll", "i'd" },
          -- the operational reason for a complete instruction, said after a comma ("he's inbound to FRA",
          -- "sequencing into DXB", "DFW metering", "ride reports", "wx at DFW"): a clause holding one of these is
          -- set aside even when it names a place, which is the reason's, never a place or condition of the instruction
          -- (one with "from" names where the aircraft comes from: asked)
          reasons = { "inbound", "sequencing", "sequence", "metering", "flow", "spacing", "ride", "rides",
                      "reports", "weather", "wx", "closed", "closure", "congestion", "sick", "medical", "arrivals",
                      "departures", "turbulence", "chop", "choppy", "bumpy", "icing",
                      -- (a holding stack named as what the vector or speed keeps clear of or prepares for: "we need
                      -- him well out of the way of the BIG stack")
                      "stack" },
          -- a sentence after a request that tells the state of the aircraft it names by a pronoun (grammar.lua
          -- G:state_sentence: "They're both heading east.", "It's at 220 right now, I think.", "It's way ahead of
          -- everybody."): `subjects` (with their copula) or `pronouns` then one of `copulas`, any of `adverbs`, then
          -- one of `predicates` (a participle of motion or a word of place, level or pace): told, never instructed
          state = { subjects = { "it's", "they're", "he's", "she's" },
                    pronouns = { "it", "they", "he", "she" },
                    copulas = { "is", "are", "was", "were", "'s", "'re" },
                    adverbs = { "both", "all", "still", "already", "now", "currently", "just", "really", "probably",
                                "definitely", "clearly", "obviously", "kind", "sort", "of", "quite", "pretty" },
                    predicates = { "heading", "going", "flying", "climbing", "descending", "turning", "tracking",
                                   "cruising", "catching", "closing", "converging", "getting", "coming", "moving",
                                   "travelling", "traveling", "gaining", "overtaking", "overshooting", "passing",
                                   "approaching", "sitting", "drifting", "routing", "heading", "running", "level",
                                   "at", "on", "about", "ahead", "behind", "close", "closer", "low", "lower", "high",
                                   "higher", "fast", "faster", "slow", "slower", "above", "below", "way", "a",
                                   "too", "near", "nearly", "almost", "well", "miles", "right", "off", "headed",
                                   "pointing", "pointed" },
                    -- (words that make the sentence a wish, a correction or a sequence: never told)
                    blocks = { "please", "you", "your", "let", "let's", "instead", "rather", "actually", "wait",
                               "no", "not", "sorry", "make", "meant", "mean", "again", "then", "also",
                               "should", "could", "can", "would", "will", "must", "need", "needs", "want", "wants",
                               "like", "shall", "may", "might", "to", "if", "when", "once", "after", "until",
                               "correction", "disregard", "negative", "one" } },
          -- the speaker's hedge with its "I'm" dropped (", not sure which way is shorter", ", not quite sure that's
          -- realistic"): a clause opening with "not", at most two of `adverbs`, one of `words`, then one of
          -- `complements` is the speaker's own (commentary.own), its "not" no negation of the instruction
          hedge = { adverbs = { "quite", "totally", "entirely", "really", "completely", "too", "so", "very", "fully",
                                "honestly" },
                    words = { "sure", "certain" },
                    complements = { "which", "whether", "if", "that", "that's", "it", "it's", "this", "how", "why",
                                    "what", "whichever" } },
          -- (and the time or purpose of the speaker's own doing after an instruction: "want CD running before I ff",
          -- "switch CD on before we pause", "save it so I can rerun", "pause until we're ready")
          while_words = { "while", "whilst", "before", "until", "till", "so" },
          -- the audience of a demonstration addressed in a sentence of its own ("Class, is that toward the bottom of
          -- the screen?", "Guess first, kids!"): such a sentence, a question too, is a remark to them (G:remark_sentence)
          audience = { "kids", "class", "guys", "students", "folks", "children", "everybody", "everyone" },
          -- a demonstrator's words showing the audience the state of things (G:commentary's `told`)
          narration = { "as you can see", "you can see", "as you see", "as we can see", "note how", "notice how",
                        "you'll notice", "you will notice", "you'll see", "you will see", "as shown" },
          -- an instructor's word to the audience on what an instruction shows, after a comma or "and" that follows
          -- it (", watch the trend arrow", "and notice the label counting down", ", see how steep that is"): one of
          -- `perception` then one of `perceived` (G:perceived), naming no aircraft, place or value
          perception = { "watch", "see", "notice", "look", "observe" },
          perceived = { "the", "how", "what", "that", "it", "him", "her", "them", "at", "its", "his", "their", "where",
                        "as" },
          -- the same action described after a complete instruction, in an instructor's words (", give him a proper
          -- vector off", ", give her a decent climb"): one of `restate_verbs`, a pronoun and a noun of the kind of an
          -- instruction said before it (`restated`, by the intent); set aside when the clause is commentary, else asked
          restate_verbs = { "give" },
          restated = { hdg = { "vector", "turn", "nudge", "kick", "heading" }, alt = { "climb", "descent", "level" },
                       spd = { "speed", "slowdown" } },
          -- the speaker's own future doing after a condition (", then when clear of BAW87 I'll send him back",
          -- ", once he's past the Ryanair we'll turn him back"): one of these, or "i"/"we" then "will", after the
          -- condition (no value, place or instruction word in it), the rest commentary; never an instruction now
          intention = { "i'll", "we'll" },
          later = { "later", "afterwards", "afterward" },
          -- (words of accounted.bare_asked.put_off that put an instruction off by a time not given, never ordering it
          -- after the one before as "afterwards" does: G:bare_asked)
          put_off_later = { "soon", "shortly" },
          lead_context = { "for", "behind", "against", "on", "with", "near", "versus", "vs" },
          leads = { "for", "to" },
          -- (a note to oneself, "note to self:", is the speaker's, to the end of its sentence)
          labels = { "reason", "purpose", "rationale", "why", "aim", "goal", "note", "comment", "context", "self",
                     "myself" },
          blocks = { "and", "then", "also", "same", "both", "either", "again", "correction", "disregard",
                     "negative", "plus", "next" },
          determiners = { "the", "a", "an", "this", "that", "our", "its", "their", "his", "her", "my",
                          "your", "s" },
          -- an experiment's label opening a sentence of its own before the request ("exp CDR-FR-ES, run 1.",
          -- "Trial 3B:", "session 2, block A."): one of these, each with an identifier (a number, or words in
          -- capitals or with digits), and nothing else up to the full stop or colon
          study_labels = { "exp", "expt", "experiment", "run", "trial", "session", "block", "condition", "cond",
                           "scenario", "scen", "case", "batch", "series", "phase", "episode", "test", "config",
                           "rollout", "ep",
                           "participant", "subject", "iteration", "rep", "replication", "day", "serial", "step",
                           "part",
                           -- (a report's parts, "as I need it for the figure in section 2")
                           "section", "figure", "fig", "table", "chapter", "appendix", "annex", "paragraph",
                           "page" },
          -- a remark in its own sentence, or its own clause after a comma, in the declarative shape (G:declared):
          -- a subject and its verb, never a request, beside an instruction ("Sorry, my supervisor is calling me.",
          -- "I am sorry, I created it a bit too low.", "Then the geometry is symmetric.", ", I created it by
          -- mistake"). It may open with an apology (`apologies`, "I am"/"I'm" before, "to" and one of
          -- `apology_verbs` and "you" after: "Sorry to disturb,"), then one of `openers`; its subject is one of
          -- `subjects`, or the words before a verb of `copulas` (no instruction word among them: "VFR traffic
          -- isn't part of this experiment"), or one of `subjects` after a phrase of `frames` and a possessive
          -- ("In my thesis we use a smaller one"). An instruction word in it is the remark's only as a noun
          -- (after one of `nouns_after` within two words: "a gentle descent") or in the past ("-ed": "I
          -- descended it by mistake"); any other, one beside one of `requests` (a wish or a modal: "it should
          -- descend", "I want it to turn") or any of `blocks` (a correction or an addition) keeps it asked
          declared = {
            apologies = { "sorry", "apologies" },
            apology_verbs = { "bother", "trouble", "disturb", "interrupt" },
            openers = { "then", "so", "if", "but", "well", "anyway" },
            subjects = { "i", "we", "it", "that", "this", "they", "there", "he", "she", "i'm", "i've", "we've",
                         "we're", "it's", "that's", "there's", "they're", "he's", "she's", "i'll", "we'll",
                         "it'll" },
            copulas = { "is", "isn't", "are", "aren't", "was", "wasn't", "were", "weren't", "allows", "permits" },
            -- (words of a remark on the study, the instruction words before its copula nouns: "Real time is a bit
            -- slow for my supervisor's patience")
            study = { "my", "our", "participant", "participants", "experiment", "thesis", "study", "supervisor",
                      "scenario", "trial" },
            -- (the people of the study as a remark's subject, before a verb in the past: "-ed" or one of
            -- past_verbs, "the participant made a mistake when creating it": G.study_subject)
            study_people = { "participant", "participants", "supervisor", "student", "students", "subject",
                             "operator", "colleague", "tester" },
            past_verbs = { "made", "did", "put", "set", "gave", "took", "forgot", "got", "had", "was", "were" },
            -- (a remark told as the speaker's belief may name a place, "Then it heads towards Utrecht, I believe")
            believed = { "believe", "think", "guess", "suppose" },
            -- (an instruction word after a question word or a word of habit is told, never instructed)
            told = { "how", "what", "whether", "why", "usually", "normally", "typically", "generally", "always",
                     "often" },
            frames = { "in", "for", "during" },
            possessives = { "my", "our" },
            -- (a copula's predicate: a subject that held its copula, as the lexer keeps it ("it" of "it's"), and the
            -- adverbs between it and the noun)
            copular_subjects = { "it", "that", "there", "he", "she" },
            predicate_adverbs = { "just", "only", "mostly", "merely", "simply", "all", "basically", "really" },
            -- (a setting's name that is also a word of judgement, its copula dropped after one of predicate_adverbs:
            -- "delete the cessna, just noise" judges the aircraft)
            judgements = { "noise" },
            -- (the adverbs marking a setting's state as told, never wished: "the detection is on anyway", "the seed is
            -- 42 btw"; "by the way" too, G:state_told)
            state_told = { "already", "anyway", "anyhow", "still", "yet", "btw", "fyi", "incidentally" },
            -- (a copula in the past tells a state, never wishes one: "the trails were on")
            past_copulas = { "was", "wasn't", "were", "weren't" },
            -- (the intents that set the simulation's settings, whose state such a clause tells: G:told_setting)
            settings = { "trail", "seed", "dtmult", "dt", "dtlook", "noise", "asas", "reso", "rmethv", "rfac", "zone",
                         "hold", "op", "ff", "resnav", "wind", "perf" },
            nouns_after = { "the", "a", "an", "this", "that", "our", "its", "their", "his", "her", "my", "your",
                            "no", "any", "some" },
            requests = { "want", "wants", "need", "needs", "like", "would", "wish", "should", "must", "can",
                         "could", "will", "may", "might", "shall", "i'd", "we'd", "i'll", "we'll", "it'll" },
            blocks = { "please", "kindly", "let", "let's", "you", "your", "instead", "rather", "actually", "meant",
                       "mean", "wait", "also", "again", "same", "both", "either", "better", "worse", "preferable",
                       -- (the speaker's own saying judged: "I typed it wrong", "I said it by mistake")
                       "said", "typed", "misspoke", "wrong", "mixed" } } },
  -- a clearance quoted whole in double quotes ('the transcript reads "KLM12, turn left heading 230"; replay it'):
  -- the words outside the quotes name it to be given again with one of `frames` and hold none of `not_frames`
  -- (text for the log, a negation, a correction or a condition), no value but a callsign or a time of day and no
  -- other word in capitals (a place); then the quoted clearance is the request, for the aircraft named outside when
  -- it names none
  quoted_clearance = {
    frames = { "replay", "replayed", "reproduce", "reproduced", "given", "give", "entered", "enter", "issued",
      "issue", "repeat", "repeated", "reissue", "reissued", "executed", "execute", "input", "applied", "apply" },
    not_frames = { "echo", "print", "log", "screen", "note", "display", "type", "typed", "write", "message", "text",
      "not", "don't", "dont", "instead", "but", "except", "correction", "without", "rather", "wrong", "never",
      -- (a condition said outside: "... over GIROM", "when level")
      "if", "when", "whenever", "once", "after", "until", "till", "before", "unless", "over", "abeam", "passing",
      "reaching", "overhead" } },
  -- a clause after a comma opening with one of these that compares an instruction with a record or justifies
  -- it (", as the transcript shows", ", which is what the controller ought to have done"): set aside when it
  -- is commentary (G:commentary: no value, place, aircraft or instruction word), else asked
  aside_comments = { "as", "which", "according",
    -- (a report's comparison with the record or the rules, ", contrary to its VFR clearance", ", consistent with
    -- the transcript"; what a defined point or a shown value stands for, ", marking the point of closest approach",
    -- ", including its level")
    "contrary", "consistent", "marking", "representing", "denoting", "including" },
  -- a relative clause telling what was done in the past ("from the point at which it was paused", "where it
  -- was stopped"): one of `past_relatives` not opening its sentence, then within three words one of `past_verbs`;
  -- set aside when it holds no value or aircraft (its verb instructs nothing)
  past_relatives = { "which", "where", "when" },
  past_verbs = { "was", "were", "had",
    -- (a report's events: "when the conflict first became apparent", "when the first alert occurred")
    "became", "occurred", "happened", "began", "started", "appeared", "arose" },
  -- words before a time said after an instruction that make it a time of the record compared with, never when to
  -- act ("as the controller did at 10:42:15", "as recorded at 15:21:40", "which is its position at 08:10:00"):
  -- such a time schedules nothing and is asked about; after one of `record_past` in an aside of a report that
  -- holds nothing else (aside_comments: ", as the controller did at 10:42:15") it is the record's, set aside
  record_time = { "as", "which", "recorded", "according", "did", "was", "were", "had", "logged", "observed",
      "corresponds", "corresponding" },
  record_past = { "recorded", "according", "did", "was", "were", "had", "logged", "observed", "corresponds",
      "corresponding" },
  -- "before it reaches the boundary", "before the Spanish border": a deadline at a part of the airspace squawk
  -- does not simulate, set aside after an instruction (flown now, it is met); its clause holds one of these,
  -- no value, place or instruction word ("before GIROM" and "before 10 minutes" are asked)
  deadline_places = { "boundary", "border", "sector", "fir", "uir", "airspace", "frontier", "handoff", "handover",
      "tma", "cta" },
  -- how gently a climb or descent is flown ("climb at 800 feet a minute, nice and gentle"): said beside the
  -- vertical speed given, it restates it; with none ("climb FL340 gently", "descend FL200 slowly") it is asked, no
  -- rate being known (an inflection of a word squawk knows, "slowly", "steadily", is asked the same)
  manner = { "nice", "gentle", "gently", "smooth", "smoothly", "slowly", "gradually", "steadily", "carefully",
      "softly", "gingerly", "leisurely", "lazily", "comfortably", "easily" },
  -- how fast a climb or descent is flown, said of its rate with no value after it ("at a good rate", "at your best
  -- rate of descent", G:rate_manner): `flown` ones ask for no more than the aircraft's own rate, which squawk flies,
  -- and are noted as "expedite" is; `asked` ones want a gentler rate than that, which no value says: asked. Their
  -- words are accounted for only in that phrase
  rate_manner = { flown = { "good", "high", "fast", "best", "maximum", "max", "expedited", "healthy",
      "brisk", "quick", "rapid", "normal", "usual", "optimum", "optimal" },
    asked = { "slow", "low", "reduced", "gentle", "moderate", "shallow", "easy", "comfortable", "minimum",
      "lower", "slower", "smaller", "small" } },
  -- the words of a climb or a descent, either way (G:opposite_motions: both said of one aircraft with no correction
  -- between is asked); "up" and "down" only as a rate's sign, straight after its value ("vs 1000 down")
  vertical_motion = { up = { "climb", "clb", "climbing", "climbs", "ascend", "ascending", "rise" },
    down = { "descend", "desc", "descent", "descending", "descends", "sink" } },
  -- a delay with no number, said after an instruction ("climb FL300 in a minute"): asked (G:delay_left)
  vague_delays = { "minute", "moment", "bit", "sec", "second", "while" },
  -- a hedge said straight after a value, closing its clause ("descend fl300 maybe", "heading 240 I think"): the
  -- speaker is unsure of the value, which is asked; a hedge before it is courtesy ("could you maybe descend",
  -- "maybe 280 knots"), and a value said loosely ("ish", "about", "or so") is the value said
  -- a place said loosely ("RAGID or so", "about RAGID", "roughly at RAGID", "RAGID-ish"): an instruction tied to it
  -- would run exactly there, so it is asked (G:hedged_place); `before` straight before the name or before an "at"
  -- before it, `after` straight after it, `after_or` after an "or" after it
  place_hedges = { before = { "about", "around", "roughly", "approximately" }, after = { "ish" }, after_or = { "so" } },
  trailing_hedges = { words = { "maybe", "perhaps", "probably", "possibly", "unsure", "hopefully" },
                      pairs = { { "not", "sure" }, { "i", "think" }, { "i", "guess" }, { "i", "believe" },
                                { "not", "certain" }, { "i", "hope" }, { "i", "suppose" }, { "i", "reckon" } },
                      -- a loose value's mark closed by a question mark ("turn to like 200-ish?"): a value the speaker
                      -- asks about, not one said loosely
                      questioned = { "ish" } },
  -- the speaker's own stop after "until" in a fast-forward with no duration ("until I say stop", "until I tell
  -- you", "until further notice"): fast time with no end (FF); anything else after "until" is an event, asked
  ff_stopped = { "stop", "stopped", "say", "tell", "told", "notice", "advised", "advise", "otherwise" },
  -- a value said to be kept, beside another instruction (G:kept_values): "FL370 is fine, just heading 150",
  -- "speed 270 is ok, descend FL150", "hdg 180 ist gut, just climb FL350" (the value, a copula or none, an
  -- approval, words that round it off, then the clause's end or another instruction); "keep FL370, just
  -- heading 150", "keep FL350 but slow down" (a verb of `verbs` before the value, a word of `only` or `but` after it)
  -- words beside lexicon.kept_as_is's that keep an aircraft taken back as it is ("..., sorry, I meant the Ryanair,
  -- the Eurowings can stay like it is": translate/handlers.lua m:aircraft_said_instead)
  said_instead_kept = { "can", "may", "should", "stay", "like", "unchanged", "be" },
  kept_as_is = { copulas = { "is", "are", "'s", "looks", "look", "seems", "stays", "remains", "ist", "bleibt" },
                 approvals = { "fine", "ok", "okay", "good", "alright", "perfect", "great", "gut", "unchanged" },
                 -- (a copula that says it alone: "FL180 stays, speed 250")
                 stays = { "stays", "remains", "bleibt" },
                 rounding = { "as", "it", "is", "for", "now", "there", "with", "by", "me", "us", "then", "so", "far" },
                 verbs = { "keep", "leave" },
                 only = { "just", "only", "nur" },
                 -- (after "keep X": "keep FL350 but slow down to 250 knots")
                 but = { "but" },
                 -- (words before the value that are part of it: "keep it at FL180", "speed 270", "your present heading")
                 units = { "speed", "heading", "hdg", "level", "altitude", "the", "your", "its", "present", "current",
                   "mach", "flight", "it", "at", "on", "flying" },
                 -- a present value named by its noun after a verb of `verbs` and one of lexicon.present ("keep its
                 -- present altitude and just turn right", "keep your current heading but slow down"): the kind kept
                 -- (G:kept_present)
                 present_nouns = { level = "alt", altitude = "alt", height = "alt", heading = "heading",
                   speed = "speed" },
                 -- the instruction word that sets each kind: a kept present value beside one of these is asked
                 present_intents = { alt = "alt", heading = "hdg", speed = "spd" } },
  -- an aircraft said to go on as it flies, in a clause of its own beside instructions to others ("..., and KLM1234
  -- stays on his route", "The KLM stays where he is.", "Lufthansa 3PK keeps his speed.", "City 1569 stay."): the
  -- aircraft, one of `verbs`, then only `words` to the clause's end (no value: "stays at FL240" is no such clause);
  -- G:aircraft_kept
  aircraft_kept = { verbs = { "stays", "stay", "remains", "remain", "keeps", "keep" },
                    words = { "where", "he", "she", "it", "they", "is", "are", "on", "his", "her", "its", "their",
                              "the", "route", "as", "speed", "level", "heading", "altitude", "present", "current",
                              "own", "for", "now", "unchanged", "same", "at", "planned", "course" } },
  -- an aircraft that a verb of `verbs` tells to be left as it flies, in a clause of its own beside instructions to
  -- others ("..., and leave the Ryanair be", "..., let the KLM be", "..., keep the easyJet as it is", "leave KLM12
  -- alone"): the verb, "the" or not, the aircraft, then at least one of `words` to the clause's end
  -- (G:aircraft_left_alone)
  -- a setting said to stay as it is, in a clause of its own after other instructions ("resolution: MVP, leave
  -- detection as is", "RESO MVP but keep the rest unchanged"): the verb, "the" or not, one to three of `nouns`,
  -- then one of `closes` ending the clause; no instruction, the clause set aside (grammar.lua G.setting_left_as_is)
  setting_left_as_is = { verbs = { "leave", "keep" },
                         nouns = { "detection", "resolution", "conflict", "cd", "cr", "asas", "reso", "wind",
                                   "winds", "trails", "trail", "noise", "method", "settings", "setting", "rest",
                                   "everything", "else", "all", "other", "others", "logging", "log" },
                         closes = { "as is", "as it is", "as it was", "unchanged", "untouched", "alone", "like that",
                                    "the same", "as they are" } },
  aircraft_left_alone = { verbs = { "leave", "let", "keep" },
                          words = { "be", "alone", "as", "it", "is", "where", "he", "she", "they", "are", "like",
                                    "that", "unchanged", "untouched", "for", "now" } },
  -- a remark where the aircraft named before goes, in a clause of its own after its instruction ("descend 5000
  -- feet, he goes to Mosnov", "..., it's going to Modlin", "..., she flies to LKMT"): a pronoun of
  -- `subjects`, words of `verbs` (one of `motion` among them), one of `to`, then the place to the clause's end
  -- (G:destination_told)
  destination_told = { subjects = { "he", "she", "it", "they", "he's", "she's", "it's", "they're" },
                       verbs = { "goes", "go", "going", "flies", "fly", "flying", "heads", "heading", "is", "are",
                                 "'s", "continues", "continuing", "proceeds", "proceeding" },
                       motion = { "goes", "go", "going", "flies", "fly", "flying", "heads", "heading", "continues",
                                  "continuing", "proceeds", "proceeding" },
                       to = { "to", "towards", "toward", "for" } },
  -- where an aircraft named goes, stated as a fact in the request's opening clause before instructions to it ("The
  -- Korean Air is going to Jeju, please make it descend ...", "KAL12 is flying to Gimpo, speed 250"): `be` and a
  -- word of `verbs`, one of `to`, then the place to the clause's end; no word of `change` anywhere in the request
  -- (G:destination_preface)
  destination_preface = { be = { "is", "are", "'s" },
                          verbs = { "going", "flying", "heading", "headed", "proceeding", "travelling", "traveling" },
                          to = { "to", "towards", "toward", "for" },
                          change = { "now", "actually", "instead", "rather", "new", "change", "changed", "set",
                                     "destination", "dest", "divert", "diverting", "reroute", "send", "not", "no",
                                     "correction", "sorry", "wrong" } },
  -- a remark that a place named is on the aircraft's route (G:route_remarks): ", which I believe is on its
  -- planned route", "? I believe BOSIO is on its route.", "? That is the Viseu beacon, on its planned route."; a
  -- clause or sentence of these words, the places named and a name before one of `place_nouns`
  route_remark = { words = { "which", "that", "this", "it", "is", "it's", "that's", "i", "we", "believe", "think",
      "already", "on", "its", "the", "planned", "filed", "route", "flight", "plan", "also", "indeed", "a", "one",
      "of", "points", "waypoints", "beacon", "point", "waypoint", "fix", "navaid", "vor" },
    place_nouns = { "beacon", "point", "waypoint", "fix", "navaid", "vor" },
    route_nouns = { "route", "plan" } },
  -- a level or speed wanted at a waypoint said without an instruction word ("when AFR1234 gets to GIROM I want it
  -- at FL250", "it should be at FL250"): the words that may come before its "at" (G:held_value)
  held_value = { "i", "i'd", "we", "we'd", "want", "like", "need", "it", "him", "her", "them", "to", "be", "at",
      "should", "must", "it's", "have", "then" },
  -- after a value or a dash, a clause opening with one of these says what should follow, no instruction
  purpose_modals = { "should", "will", "would", "must" },
  -- verbs that describe the scenario running after it ("the scenario feels a bit empty")
  -- the prepositions before "the <name> scenario" that speak of the scenario the study is at, no file to load
  -- ("we start now with the Frankfurt scenario", "aircraft for the Stuttgart scenario")
  scenario_spoken_of = { "with", "for", "of", "in", "about", "from" },
  scenario_described = { "feels", "felt", "looks", "seems", "is", "was", "gets", "becomes", "appears", "sounds" },
  -- modals after "then" and the speaker ("Then we can see the conflict develop"): what the speaker does next
  own_modals = { "can", "could", "will", "may", "might", "should" },
  -- abbreviations written in capitals that name no place
  not_names = { "vfr", "ifr", "fms", "atis", "qnh", "qfe", "cpa", "los", "eta", "etd", "sid", "star", "nm",
      "kts", "fpm", "agl", "msl", "amsl", "rnp", "ctr", "tma", "atz", "ias", "cas", "stca", "fdr",
      -- an air traffic unit's abbreviation after its place ("Barcelona ACC", accounted.facilities)
      "acc", "uac", "twr",
      -- a study's questionnaires and measures ("fill in the NASA-TLX")
      "nasa", "tlx", "nasa-tlx" },
  -- words before a waypoint that a direct-to flies past ("skip TP1 and go direct TP2")
  passed_over = { "skip", "skipping", "bypass", "bypassing", "omit", "omitting", "not", "instead" },
  below = { "below", "under" },
  above = { "above", "over" },
  -- a level said against another aircraft's ("1000 feet lower than KLM880", "2000 ft above the Airbus")
  level_below = { "below", "under", "lower", "beneath" },
  level_above = { "above", "over", "higher" },
  relative = { "present", "current", "actual", "by" },
  -- an amount after "of" straight after one of `change_of_verbs` ("go down of 2000 feet", "climb of 1000", "reduce
  -- of 10 knots", "turn on the right of 30 degrees"), or after such a verb, "the" or "its" (or neither) and one of
  -- `change_of_nouns` ("reduce the velocity of 40 knots"), is the size of the change: Italian "di", Spanish,
  -- Portuguese and French "de", said as "of" (G:change_of). After any other word ("a level of 9000", "heading of
  -- 270", "to a speed of 250") it is the value itself.
  change_of_verbs = { "climb", "climbs", "climbing", "descend", "descends", "descending", "up", "down", "increase",
                      "increases", "reduce", "reduces", "decrease", "decreases", "raise", "lower", "drop", "slow",
                      "accelerate", "decelerate", "left", "right" },
  change_of_nouns = { "speed", "velocity", "altitude", "level", "height", "heading" },
  -- words after an amount that name what it is counted from ("by 20 knots relative to what it is doing",
  -- "compared with what it flies now"): the present value
  counted_from = { "relative", "compared", "relatively" },
  -- ("actual": the false friend of the present one, in several languages)
  present = { "present", "current", "actual", "continue" },
  -- verbs that keep a value as it is ("maintain heading", "keep your heading": said with none, the present one)
  keep_verbs = { "maintain", "keep", "hold" },
  same_as = { "match", "same", "as" },
  -- After "as" and an aircraft, what it did or is: the aircraft is compared with ("as EZY45 did")
  compared_doings = { "did", "does", "do", "has", "had", "was", "were", "is" },
  -- the words of likeness before "to" and an aircraft compared with ("a new aircraft similar to ANA51")
  compared_likeness = { "similar", "identical", "comparable" },
  -- Before "like", words that make it a wish ("I'd like", "we would like"), not a comparison
  wish_before_like = { "would", "i'd", "we'd", "you'd", "they'd", "i", "we", "you", "they", "should", "'d",
      "really", "also", "now" },
  -- switches
  off = { "off", "disable", "disabled", "deactivate", "deactivated", "hide", "stop", "don't", "dont", "without", "remove",
          "disengage", "disengaged", "disconnect", "disconnected", "inhibit", "inhibited" },
  -- verbs of an item made to go, switching it off after "make", "let" or "have" ("make the trails disappear"); a
  -- reason's ("show trails so aircraft disappear") switches nothing
  off_made = { "disappear", "vanish" },
  off_after = { "anymore", "longer" },
  -- an aircraft's being wanted no more, the reason for removing it ("WZZ1523 is not needed anymore, remove it")
  unneeded = { "needed", "required", "wanted", "necessary" },
  -- the speaker's need of an aircraft denied before it is removed ("we will not need AFR1142 any more, so ...",
  -- grammar.lua G:need_denied): the words before the aircraft and after it
  need_denied_before = { "we", "i", "will", "would", "do", "does", "not", "won't", "don't", "no", "longer", "need",
      "want", "require", "really", "actually" },
  need_denied_after = { "any", "more", "anymore", "longer" },
  -- an aircraft said not to belong where it flies, before it is removed later in the request ("Virgin 27G
  -- shouldn't be in this exercise at all; delete him", "KLM12 isn't part of the scenario, remove it",
  -- G:presence_denied): the aircraft, then only these words, a negation and one of `presence_places` among them
  presence_denied = { "should", "shouldn't", "is", "isn't", "does", "doesn't", "not", "really", "be", "belong", "in",
                      "part", "of", "this", "the", "our", "at", "all" },
  presence_places = { "exercise", "scenario", "simulation", "sim", "run", "session", "here",
      -- (an aircraft taken "out of the picture": out of the run)
      "picture" },
  -- verbs that end a movement: the direction after them is the one stopped, not the one flown (handlers:direction)
  halted = { "stop", "stops", "stopping", "cease", "halt", "discontinue", "terminate", "interrupt", "arrest" },
  -- words between "instead of"/"rather than" and the value they replace ("instead of the default 1.05",
  -- "rather than the current 250"): that value is still the one replaced (grammar.lua G:replaced_values)
  replaced_lead = { "the", "default", "current", "usual", "original", "old", "previous", "present", "standard",
      "existing", "value", "setting", "of" },
  -- countries, as later words of airlines' telephonies name them ("FLYING BULGARIA", "AIR PORTUGAL"): said alone
  -- before a flight number, a country names no one airline (handlers.lua m:telephony_part_only)
  countries = { "albania", "algeria", "argentina", "armenia", "austria", "azerbaijan", "belgium", "bosnia",
      "brazil", "bulgaria", "canada", "chile", "china", "colombia", "croatia", "cyprus", "czech", "denmark",
      "egypt", "estonia", "ethiopia", "finland", "france", "georgia", "germany", "greece", "hungary", "iceland",
      "india", "indonesia", "iran", "iraq", "ireland", "israel", "italy", "japan", "jordan", "kenya", "korea",
      "latvia", "lebanon", "lithuania", "luxembourg", "malaysia", "malta", "mexico", "moldova", "montenegro",
      "morocco", "nepal", "netherlands", "nigeria", "norway", "pakistan", "peru", "philippines", "poland",
      "portugal", "qatar", "romania", "russia", "serbia", "singapore", "slovakia", "slovenia", "spain",
      "sweden", "switzerland", "syria", "taiwan", "thailand", "tunisia", "turkey", "ukraine", "uzbekistan",
      "vietnam", "yemen", "macedonia", "kosovo", "libya", "mongolia", "oman" },
  -- verbs that end fast time, said before the fast-forward they name ("stop the fast-forward", "end fast
  -- forward"): that fast time ended (OP), never started (handlers_other: fast_forward)
  ff_ended = { "stop", "end", "cancel", "quit", "exit", "finish", "abort", "halt", "cease", "terminate",
      "discontinue", "interrupt" },
  -- ("connect also the VNAV": "conectar", as "disconnect" is off)
  on = { "on", "enable", "activate", "show", "start", "use", "engage", "engaged", "connect", "connected" },
  -- a change of speed said by its direction alone ("go faster", "slow down")
  faster_slower = { "faster", "slower", "accelerate", "decelerate" },
  -- a runway, or an approach named by its runway ("runway two seven left", "the ILS two seven right", "ILS
  -- approach 27 left"), and the sides a runway's number is said with: part of its name
  runway = { "runway", "rwy", "land", "landing", "ils", "loc", "localizer", "localiser", "rnav", "rnp" },
  runway_sides = { "left", "right", "center", "centre" },
  -- turns and compass points
  left = { "left" },
  right = { "right" },
  -- verbs of going before a compass point that is the heading ("flying south")
  compass_verbs = { "flying", "heading", "going", "tracking", "travelling", "traveling", "moving", "pointing",
      "facing", "flies", "headed" },
  -- words between a verb of going and its compass point that leave the point as said ("the Shamrock heading out
  -- west", "the one going due north", "the Ryanair flying back east", "the Embraer heading off south")
  compass_particles = { "due", "out", "off", "back", "away" },
  -- verbs of going in the present that describe an aircraft only after "that" or "which" ("the easyJet that goes
  -- to north", "the one which heads east"; "the easyJet goes north" stays an instruction's words)
  compass_relative_verbs = { "goes", "moves", "heads", "proceeds" },
  -- verbs of coming before "from" and the compass point an aircraft flies away from ("the one coming from the
  -- east" flies west: G:way_said)
  compass_from_verbs = { "coming", "approaching", "arriving", "inbound" },
  -- words that make a compass point a direction to lean toward, not a heading ("more to the north", "a bit
  -- further east", "slightly west"): no heading value, asked
  vague_direction = { "more", "further", "farther", "slightly", "bit", "little", "somewhat", "something" },
  compass = { north = 0, east = 90, south = 180, west = 270,
              northeast = 45, southeast = 135, southwest = 225, northwest = 315 },
  -- a wind named by where it blows from ("a westerly at 40 knots"): that direction in degrees
  wind_points = { northerly = 360, easterly = 90, southerly = 180, westerly = 270, northeasterly = 45,
                  southeasterly = 135, southwesterly = 225, northwesterly = 315 },
  -- fractions of an hour, a minute or a second said in words ("half an hour", "a tenth of a second")
  fractions = { half = 0.5, quarter = 0.25, fifth = 0.2, tenth = 0.1, twentieth = 0.05, hundredth = 0.01 },
  -- how many times real time, said in words
  multipliers = { twice = 2, double = 2, thrice = 3, triple = 3, quadruple = 4, half = 0.5 },
  -- a spoken callsign matched to an aircraft it does not spell exactly is
  -- confirmed by a question; strict: whenever more than one aircraft flies,
  -- and with one aircraft too when `alone` (any airline, digit or letter that
  -- differs asks); else unless the airline and the digits both match at
  -- least this well (similarity 0-1)
  -- airline_alone: "the Ryanair" (an airline after "the", no flight number) names the one aircraft of that
  -- airline flying; with two or more, or none, squawk asks
  -- airline_alone_addressee: so does an airline said alone, capitalised, as a clause's addressee
  -- ("Lufthansa, mach .80") with no callsign in its clause
  -- a clause counting the instructions said before it ("two things in one line", "three separate commands", "both at
  -- once", "one instruction, one command"; grammar.lua's G.instruction_counts): its first word ("one" only before
  -- one word of them), the words that may follow
  instruction_counts = {
    counts = { both = true, one = true, two = true, three = true, four = true, all = true },
    words = { things = true, thing = true, instructions = true, instruction = true, commands = true, clearances = true,
              changes = true, separate = true, ["in"] = true, one = true, line = true, go = true, transmission = true,
              call = true, at = true, once = true, together = true, of = true, them = true, the = true, same = true,
              time = true, three = true, shot = true, message = true, command = true, each = true } },
  -- a bank angle limit [deg] above this is steeper than any aircraft squawk flies banks: asked, never set
  max_bank_deg = 60,
  -- words before the heading an aircraft flies now, said beside a relative turn ("from 090", "heading was 240",
  -- "you're on 180"): where the turn starts (handlers_values.lua)
  present_heading_words = { "from", "was", "on", "currently", "presently" },
  callsign_confirm = { airline = 0.5, digits = 0.6, strict = true, alone = true, airline_alone = true,
    airline_alone_addressee = true },
  -- a spoken waypoint name matched to a known one at least this well (0-1)
  -- is taken as said; below it (down to 0.5) squawk asks "did you mean ...?"
  waypoint_confirm = 1.0,
  -- a speed [kt] below this, typed for an aircraft created in the air ("cre tst9 a320 48 11 90 fl200 25") or
  -- typed as SPD's ("spd 25"), is no speed it can fly: asked, never run
  min_airborne_kt = 40,
  -- a speed typed as SPD's or CRE's, with no unit (nodes.lua M.typed_speed_question): over max_kt [kt CAS] it is
  -- faster than any airliner flies; under min_kt slower than any jet flies in the air, or any aircraft flying
  -- fast_kt or more: asked, naming why
  typed_speed = { min_kt = 100, max_kt = 400, fast_kt = 200 },
  -- a vertical speed [ft/min] typed below this as VS's ("vs 15") may have lost its zeros: asked
  min_typed_fpm = 100,
  -- a level typed as ALT's, a bare number under min_ft [ft] (nodes.lua M.typed_level_question), is asked, offering
  -- the flight level it may be typed short for when that lies within max_fl [FL]
  typed_level = { min_ft = 1000, max_fl = 600 },
  -- a level or heading said digit by digit and run on into a speed before its unit with no break ("flight level
  -- eight zero two four zero knots"; grammar.lua G.run_on_values): the words naming the value, and what each part
  -- can be: a flight level of two or three digits within `level` [FL], a heading of three digits within `heading`
  -- [deg], a speed of three digits, the first no zero, within `speed` [kt]
  run_on = { level_words = { "level", "fl" }, heading_words = { "heading", "hdg" }, level = { 30, 600 },
    heading = { 0, 360 }, speed = { 100, 399 } },
  -- a number with no unit after "at" after a cleared flight level, read as the vertical speed [ft/min] within
  -- these bounds ("descend FL120 at one thousand five hundred"; "at 250" is a speed, asked)
  rate_after_level = { 500, 6000 },
  -- a single number word said as a level with no "thousand" ("descend one") is read as that many thousand feet
  -- only within this distance [ft] of the aircraft's present level; farther, a level cut short, asked
  bare_thousands_reach = 10000,
  -- a number said group-wise in words ("one hundred twenty") read as a flight level where no unit says so (a
  -- creation's or a move's level): the flight levels it may name, and the altitude [ft] an aircraft moved must
  -- fly at for it (lower down, feet or a level? asked)
  groupwise_levels = { 100, 450 }, groupwise_from_ft = 10000,
  -- a navaid said by its navdata name ("direct Canarsie") is looked for this near the aircraft [NM]
  navaid_range_nm = 250,
  -- navaids of one name this near each other [NM] are one station ("Rodos": the NDB ROS, the VOR-DME RDS and
  -- the TACAN ROD); its name said alone is its VOR
  navaid_station_nm = 5,
  -- a navaid this near an airport [NM] stands for the same city ("Sherbrooke": the YSC VORTAC, 8 NM from CYSC)
  city_nm = 30,
  -- an airport this near a navaid named after a city [NM] is one of that city's ("Montreal": CYUL, 4 NM from the
  -- MONTREAL NDB; NavDb::kBesideNavaidNm)
  beside_navaid_nm = 10,
  -- a large or medium airport this near a navaid named after a city [NM], its own name another, is where that
  -- city's name may mean ("Lille": LFQQ "LESQUIN", 4.9 NM from the LL NDB; not EGLC, 9 NM from LAMBOURNE)
  city_navaid_nm = 6,
  -- a city said as a destination or origin and found by no airport near the aircraft is its region's when its
  -- nearest airport lies within region_nm [NM] of the aircraft and every other airport of that name
  -- region_ratio times as far or farther ("destination Cordoba" from Buenos Aires: SACO 350 NM, not LEBA,
  -- Spain, 5400 NM)
  region_nm = 1000,
  region_ratio = 4,
  -- the airports named after a city whose surroundings (city_nm) hold the city's other airports, at most
  -- ("Montreal Trudeau": CYUL beside CYMX "MONTREAL INTL MIRABEL")
  city_anchors = 6,
  -- the little words inside a place's name ("San Sebastian de los Reyes") that the navdata's short form of
  -- it leaves out ("S.S. REYES"); a name of three words or more said whole is looked for as said and as the
  -- initials of its words before the last, these left out, then the last word
  name_particles = { "el", "de", "del", "la", "las", "los", "le", "les", "du", "des", "da", "do", "dos", "di",
    "van", "von", "der", "den" },
  -- a navaid said by its name within this of a large airport stands on it: "create ... at Marseille" is the
  -- airport (LFML), not its NDB (MJ) [NM]
  on_airport_nm = 1,
  -- a navaid named after a city within this of the large airport bearing the city's name [NM] is one place with
  -- it: "direct Sydney" (the SY VOR-DME 0.3 NM from YSSY, the BN VOR-DME 1.6 NM from YBBN) is the airport
  navaid_by_airport_nm = 2,
  -- a place's name said straight before a latitude and longitude after one of these names that position when the
  -- navdata has a place of the name within named_position_nm of it ("over Schiphol (52.31 N, 4.76 E)":
  -- grammar.lua G:place_at_its_position) [NM]
  named_position_leads = { "at", "over", "near", "above", "around", "to" },
  named_position_nm = 10,
  -- words that make a sentence after a limit's place more than a remark on it ("until OSTER. Not below.", "... Or
  -- faster."): grammar.lua G:remark_sentences
  remark_not = { "not", "no", "never", "don't", "dont", "do", "below", "above", "less", "more", "faster", "slower",
    "minimum", "maximum", "min", "max", "or", "greater", "higher", "lower", "after", "afterwards", "later",
    "resume", "cancel", "unless", "if", "when", "once", "until", "till", "instead", "only", "except" },
  -- answers that confirm a question ("did you mean BAW123?")
  yes = { "yes", "affirm", "affirmative", "correct", "yep", "yeah", "confirmed", "confirm",
          -- (Turkish)
          "evet" },
  -- answers to "What does 'W' mean?" that say W carries nothing ("ignore it", "nothing",
  -- "just a comment"): the request is read again with W explained; never offered for a
  -- negation or a condition (lexicon.accounted.negation, condition words), which must be restated
  ignore = { "ignore", "it", "that", "this", "word", "nothing", "skip", "disregard", "means", "just", "a",
             "comment", "remark", "filler", "please", "the" },
  -- what squawk does not simulate: a phrase starts at one of `words` (with
  -- one of `near` within `window` words after it, 4 by default, when given) and runs to the end
  -- of its clause; it is named in the reply, never translated. `takes_time`: a manoeuvre flown for a
  -- while, so an instruction after "then" waits for it and is asked about, never sent now; `one_value`:
  -- the phrase ends at its first number ("QNH 1021, 180 knots": the speed is an instruction); `and_near`:
  -- { words, n }, one of these within n words after the `near` word too; `clause`: the phrase goes on
  -- through instruction words up to its first comma (all of "expect to resume own navigation to X" is announced);
  -- `subject`: the phrase is one only straight after one of these words; `own_clause`: with `last`, a clause
  -- after a comma opened by an imperative verb ("until 5 miles final, descend to 3000 feet") may follow it;
  -- `after_heading`: the phrase is one only after a heading value, with at most "to", "vectors" or a comma
  -- between them (G:after_heading); `bare`: the word is one only said alone in its clause (G:said_bare); `manner`:
  -- one only said as an instruction's manner, the phrase its word alone (G:said_as_manner); `rate_manner`: the
  -- word is a rate's, said as a manner with no value (G:rate_manner), the phrase that manner;
  -- `no_value`: none with a value said straight after its word (G:value_next); `routed`: a place it names off
  -- the route of the one aircraft addressed is asked (G:limit_off_route); `no_number_after`: no phrase when a
  -- number follows its `near` word; `not_to_profile`: none said to an aircraft flying its route's profile
  -- (G:profile_speed_resumed); `station_before`: one or two capitalised words straight before its word, the
  -- station named, are the phrase's too; `clock`: see its entry
  not_simulated = {
    -- ("squak", "sqwk": squawk typed short)
    { what = "transponder codes", words = "squawk squawking sq squak sqwk sqk",
      near = { "ident", "code", "standby", "mode", "vfr", "#number" } },
    { what = "transponder codes", words = "transponder ident" },
    { what = "radio frequencies", words = "contact monitor frequency freq" },
    -- a hand-off said with another verb before the frequency ("call Vienna on 129.2", "switch to approach
    -- 119.1", "over to Wien 134.35", "go to 129.2")
    { what = "radio frequencies", words = "call switch over go change", near = { "#frequency" } },
    -- ("hand it to London 133.6", "hand him off to approach on 119.1": the hand-off said with "hand")
    { what = "radio frequencies", words = "hand handoff", near = { "#frequency" } },
    -- "then Gander on 128.5", "Shanwick on one two seven decimal six": a station named, then "on" and its frequency
    -- (`station_before`: the station's name straight before "on" is the phrase's too, G:not_simulated)
    { what = "radio frequencies", words = "on", near = { "#frequency" }, window = 1, station_before = true },
    -- (a newcomer's plain words for the hand-off, the station's name and kind between: "then to talk to Lisbon
    -- control on 132.8", "speak to Madrid control on one three two decimal seven")
    { what = "radio frequencies", words = "talk speak", near = { "#frequency", "control", "approach", "tower",
      "centre", "center", "radar", "ground", "departure", "director", "information" }, window = 6 },
    { what = "approach clearances", words = "ils rnav rnp localizer localiser glideslope glidepath vor",
      near = { "approach", "established", "intercept", "cleared", "runway", "#number" } },
    { what = "approach clearances", words = "cleared clear",
      near = { "approach", "land", "landing", "takeoff", "take-off", "ils", "visual", "option" } },
    { what = "approach clearances", words = "visual", near = { "runway", "approach" } },
    -- "land 27 left", "runway 09 right", "rwy two seven": a runway named by its number straight after the word
    -- (the side after it is the runway's, never a turn: G:runway_sides)
    { what = "approach clearances", words = "land landing runway rwy", near = { "#number" }, window = 1 },
    -- ("join the river visual runway one niner": a named visual approach joined, its name before "visual")
    { what = "approach clearances", words = "intercept established join",
      near = { "localizer", "localiser", "glideslope", "ils", "final", "visual" } },
    { what = "altimeter settings", words = "altimeter qnh qfe", one_value = true },
    -- "save the state so I can rerun", "save the scenario": a snapshot of the run written out (BlueSky's SAVEIC),
    -- which squawk has no command for ("save fuel" saves no state)
    { what = "saving the simulation's state", words = "save saving", near = { "state", "scenario", "sim",
      "simulation", "snapshot", "situation", "traffic", "everything", "progress", "setup" }, window = 3,
      through = "state scenario sim simulation" },
    -- ("heading 140 and zoom out a bit", "pause, and center on speedbird 8ck": the scope's view, which its own
    -- controls set; no simulator command)
    { what = "the display's zoom (set with the scope's own controls)", words = "zoom", near = { "in", "out" }, window = 1 },
    { what = "centring the display (set with the scope's own controls)", words = "centre center", near = { "on" }, window = 1,
      after_instruction = true },
    -- ("..., radar service terminated", "radar services limited": the service the controller gives, told the pilot)
    { what = "radar services", words = "service services", near = { "terminated", "terminating", "limited", "radar" },
      window = 2 },
    -- "JetBlue 1123, wind 310 at 15, reduce 190": the surface wind told to the aircraft addressed, no
    -- setting of the simulation's wind (said with no callsign before it, "wind 310 at 15" is WIND's)
    { what = "wind reports", words = "wind", near = { "#number" }, window = 1, after_callsign = true },
    -- "keep speed 280 until VAKNO", "maintain FL200 till DETAK": the value is flown now, its end at the
    -- place is not kept; said last only (anything after it, "then contact tower", waits for it: asked);
    -- `routed`: the place is on the route of the one aircraft addressed (else the limit is placed nowhere: asked)
    { what = "limits that end at a place", words = "until till", near = { "#waypoint" }, after_instruction = true,
      last = true, own_clause = true, routed = true },
    -- ("Viper 11, angels 18, buster": military brevity for the most speed the aircraft has, which squawk's
    -- instructions set as a value only)
    { what = "military speed brevity", words = "buster" },
    -- "speed 250 until passing FL100", "250 knots till leaving one zero thousand": the same limit ending at a level
    -- passed, said last
    { what = "limits that end at a level", words = "until till", near = { "passing", "leaving", "through" }, window = 1,
      after_instruction = true, last = "passing leaving through flight level fl feet ft thousand hundred altitude" },
    -- "maintain 8000 until established", "till established on the localizer": the same limit ending on the
    -- approach, said straight after the word and last (`last`: the words it may hold, a comma among them:
    -- "until established, cleared ILS runway 10" closes with the approach clearance)
    { what = "limits that end on the approach", words = "until till", near = { "established" }, window = 1,
      after_instruction = true,
      last = "established on the localizer localiser ils rnav rnp gps visual final approach , cleared for runway rwy l r c" },
    -- "speed 160 until 4 DME", "170 knots till 5 miles final, cleared ILS 01L": the same limit ending at the
    -- final approach's 3 to 6 miles ("4 miles on final"), its unit said, an approach clearance after it at most
    -- (01L is "01" and "l"); a value after it ("until 5 DME then 140"), "until 4" (no distance) and a limit further out
    -- ("250 kts till 10 dme", a point squawk cannot place: R51) are asked
    { what = "limits that end at a distance", words = "until till", own_clause = true,
      near = { "3", "4", "5", "6", "three", "four", "five", "six" }, window = 1,
      -- ("til 5 fnl": a count straight before "final" is its miles, the unit left out as on a strip)
      and_near = { { "dme", "miles", "mile", "nm", "final" }, 2 }, after_instruction = true,
      last = "dme miles mile nm final on out from touchdown threshold the , cleared for ils localizer localiser "
        .. "approach runway rwy l r c" },
    -- "reduce 160 knots to four DME", "speed 180 to 5 miles final": "to" for "until" before the same limit, its
    -- DME or "final" said (a zone's "radius to 4 nm" is no limit)
    { what = "limits that end at a distance", words = "to", own_clause = true,
      near = { "3", "4", "5", "6", "three", "four", "five", "six" }, window = 1,
      and_near = { { "dme", "final" }, 2 }, after_instruction = true,
      last = "dme miles mile nm final on out from touchdown threshold the , cleared for ils localizer localiser "
        .. "approach runway rwy l r c" },
    -- "climb FL250, cancel speed restriction", "cancel level restrictions": a restriction lifted, which squawk
    -- (flying each instruction as given) does not keep
    -- (a value after a comma is no part of it, `stops_at_value`: "cancel speed restrictions, 250 knots" gives a speed)
    { what = "restrictions lifted", words = "cancel", near = { "restriction", "restrictions" },
      through = "speed level altitude", stops_at_value = true },
    -- ("Air Wisconsin 4120, delete speed restrictions": the restriction deleted, never the aircraft)
    { what = "restrictions lifted", words = "delete remove", near = { "restriction", "restrictions" }, window = 3,
      through = "speed level altitude", stops_at_value = true },
    -- "EZY45KL resume normal speed", "DAL14 climb FL250, resume normal speed": said to an aircraft, its speed
    -- restriction lifted (said alone, "resume normal speed" is the simulation's rate, DTMULT 1; said alone to an
    -- aircraft flying its route's profile, the profile's speed given back: VNAV ON)
    { what = "restrictions lifted", words = "resume", near = { "speed" }, window = 2, to_aircraft = true,
      not_before = "speed", through = "speed", stops_at_value = true, not_to_profile = true },
    -- "climb FL150, when passing FL100 speed your discretion", "speed at pilot's discretion": the speed left to the
    -- pilot, a restriction lifted
    { what = "restrictions lifted", words = "speed", near = { "discretion" }, window = 3, to_aircraft = true },
    -- "turn right heading 330, vectors for runway 28", "vectoring for the ILS": what a vector is for, a
    -- runway squawk does not fly to
    { what = "approaches to a runway", words = "vectors vectoring vector",
      near = { "runway", "rwy", "ils", "final", "approach", "localizer", "localiser", "landing", "for" } },
    -- "turn right heading 090, vector to IDEKO": where a vector leads, told to the pilot; the heading is flown,
    -- no direct-to is given ("vector to 300" names a heading, `no_number_after`: a number straight after the near word)
    { what = "vectors toward a place", words = "vectors vectoring vector", near = { "to", "towards" }, window = 1,
      no_number_after = true },
    -- "turn right heading 110, vectors Venice": the place named straight after the word (capitalised, or a
    -- place squawk knows), after an instruction
    { what = "vectors toward a place", words = "vectors vectoring", named_after = true, after_instruction = true },
    -- "turn left heading 060, vectors to rejoin the track at DOBAK", "heading 200 to intercept the airway at
    -- LAMSO": what the heading is flown for, the place where it ends; the heading is flown, no direct-to is given
    -- ("heading 200, then rejoin the route at DOBAK" and "cleared to rejoin ..." are instructions of their own)
    { what = "what a heading is flown for", words = "rejoin rejoining intercept intercepting join joining regain",
      subject = "to", after_heading = true, clause = true },
    -- "maintain VFR at or below 4500", "VFR on top", "remain VFR conditions": flight rules, with the levels
    -- they allow; squawk flies no flight rules, and the level said with them is no cleared altitude ("maintain
    -- VFR at 4500", one level, is the altitude to fly)
    { what = "flight rules", words = "vfr", near = { "below", "above", "on", "conditions" } },
    -- "caution similar callsign", "caution wake turbulence": a warning to the pilot, no instruction
    -- (`through`: instruction words that stay in the phrase: wake turbulence is no NOISE command)
    { what = "cautions", words = "caution", through = "turbulence" },
    -- traffic information ("traffic 2 o'clock, 5 miles, eastbound, altitude indicates 3500") runs to the
    -- end of the request: the words in it describe the other aircraft, they instruct nobody (the aircraft
    -- may be named before its clock position: "traffic, an Emirates 777, at your two o'clock")
    { what = "traffic information", words = "traffic", near = { "o'clock", "oclock", "clock" }, window = 9,
      to_end = true },
    -- ("Speedbird 2490, traffic at one one zero", "traffic at FL110, climb FL170"): the level or place said after
    -- "traffic at" is the other aircraft's, never one to fly (a clause opening with an imperative verb after a
    -- comma is still an instruction)
    { what = "traffic information", words = "traffic", near = { "at" }, window = 1, to_end = true },
    -- ("KLM12, DLH34, traffic information, both of you, opposite direction same level", "traffic info: A320 crossing
    -- ahead"): the service named and the other aircraft told by the way it flies or where it is, to whoever is
    -- addressed; it shows nobody's position (a clause opening with an imperative verb after a comma is still an
    -- instruction). Said with no such description, "DLH2AE traffic info please" asks for that aircraft's data.
    { what = "traffic information", words = "traffic", near = { "information", "info" }, window = 1, to_end = true,
      and_near = { { "opposite", "crossing", "converging", "overtaking", "same", "reciprocal", "climbing", "descending",
                     "ahead", "behind", "passing", "below", "above", "beneath", "underneath", "o'clock", "oclock",
                     "clock" }, 10 } },
    -- ("descend FL320, traffic opposite direction FL340", "maintain FL370, traffic crossing left to right, a
    -- Volotea at FL350": after an instruction, traffic told by the way it flies; its level is the other aircraft's)
    { what = "traffic information", words = "traffic", window = 2, after_instruction = true, to_end = true,
      near = { "opposite", "crossing", "converging", "overtaking", "same", "reciprocal", "climbing", "descending",
               "ahead", "behind", "passing", "below", "above", "beneath", "underneath" } },
    -- ("turn left 20 degrees, traffic is KLM", "descend FL280, traffic is an Emirates at FL300": after an
    -- instruction, the other aircraft named after "traffic is"; its airline, callsign or level is no addressee or
    -- value of the instruction)
    { what = "traffic information", words = "traffic", near = { "is" }, window = 1, after_instruction = true,
      to_end = true },
    -- ("climb FL100, there's an inbound sitting at one one zero": after an instruction, an arrival told by where
    -- it is; its level is the other aircraft's)
    { what = "traffic information", words = "inbound", window = 2, after_instruction = true, to_end = true,
      near = { "sitting", "holding", "level", "below", "above", "beneath", "underneath" } },
    -- "FPA -3 and speed 180": a flight path angle, which squawk's aircraft do not fly by (its value with it)
    { what = "flight path angles", words = "fpa", near = { "#number" }, window = 1 },
    -- "you are number two behind the Emirates", "number one for the approach": a place in the sequence, told
    -- to the pilot, its number straight after the word ("the random number generator with 7" is none)
    -- ("Mach number 0.78" names the speed's unit, no sequence)
    { what = "approach sequences", words = "number", near = { "#number" }, window = 1, not_after = "mach" },
    -- "say fuel remaining", "souls on board?", "report your fuel state", "report endurance": what a controller
    -- asks of an aircraft in distress, answered by the pilot (squawk simulates no fuel and no persons on board)
    { what = "reports of fuel and persons on board", words = "fuel souls persons", window = 2,
      near = { "remaining", "endurance", "board", "state", "status" }, through = "state status" },
    { what = "reports of fuel and persons on board", words = "endurance" },
    -- "advise when able to climb FL300", "say when able FL300", "report if able higher", "let me know when able
    -- direct KORRY": the pilot's report asked for, of what it can fly, up to the end of its clause; the
    -- instruction named is no clearance (a clause opening with an imperative verb after a comma is one; `able`: its
    -- "when" or "if" opens no condition)
    { what = "reports of what the aircraft is able to fly", words = "advise report say tell know", near = { "able" },
      window = 3, clause = true, able = true },
    -- ("say when ready to climb FL300", "advise when ready for descent": the same, of when it is ready)
    { what = "reports of what the aircraft is able to fly", words = "advise report say tell know", near = { "ready" },
      window = 3, clause = true, able = true },
    -- "report level FL150", "report level at 5000", "report heading 090": the pilot's report on reaching that
    -- value, no clearance to it (`through`: the state word stays in the phrase, its value with it)
    { what = "position reports", words = "report reporting", near = { "level", "altitude", "heading", "speed", "mach" },
      window = 1, and_near = { { "#number", "fl", "flight", "at", "on" }, 2 }, through = "level altitude heading speed mach" },
    -- "report passing FL100", "report established", "report steady": a report the pilot makes, no instruction
    { what = "position reports", words = "report reporting",
      near = { "passing", "reaching", "leaving", "established", "abeam", "overhead", "over", "crossing",
               "vacating", "when", "at", "steady" } },
    -- "cross GOMUP at or after 1215", "crossing 55N20 not before one two one five": a time to cross a place at
    -- (`clock`: only before a clock time of four figures after "after" or "before", G:clock_limit; the phrase
    -- ends with that time)
    { what = "time constraints", words = "cross crossing", near = { "#waypoint" }, window = 1,
      and_near = { { "after", "before" }, 3 }, clock = true },
    -- "climb FL400, on reaching report", "when level report": the report asked for said after its condition,
    -- no condition of an instruction
    { what = "position reports", words = "on upon when once", near = { "reaching", "level" }, window = 1,
      and_near = { { "report" }, 1 } },
    -- "descend 4000, report the field in sight", "report traffic in sight": after an instruction, a sighting the
    -- pilot reports, no instruction (alone it is asked)
    { what = "position reports", words = "report", near = { "sight", "visual" }, window = 4,
      after_instruction = true, clause = true },
    -- "descend FL70, report DAVOT", "direct LAM, report overhead": after an instruction, the report the pilot makes
    -- passing a waypoint, no instruction (alone it is asked)
    { what = "position reports", words = "report", near = { "#waypoint" }, window = 1, after_instruction = true,
      clause = true },
    -- "turn right 15 degrees, report heading": after an instruction, the readback of what it set is a
    -- report the pilot makes (alone, "report heading" asks for the aircraft's state: POS; so does one after an
    -- instruction that set another measure, "descend FL190 and report your heading", G:report_of_set)
    { what = "position reports", words = "report", near = { "heading", "level", "altitude", "speed", "mach" },
      after_instruction = true, to_end = true, of_set = true },
    -- "KLM12 read back FL110", "readback was heading 200": the values a pilot read back are the pilot's words, no
    -- clearance (what was cleared, said after them, is read: grammar.lua readback_reported)
    { what = "readbacks of a clearance", words = "read", near = { "back" }, window = 1,
      and_near = { { "#number", "fl", "flight", "heading", "level", "altitude", "speed", "mach" }, 2 } },
    { what = "readbacks of a clearance", words = "readback", near = { "#number", "fl", "flight", "heading", "level",
      "altitude", "speed", "mach", "was" }, window = 1 },
    -- "the student cleared him direct LUX", "he was already cleared to FL100": what someone did, told in the
    -- past tense after a person, is a report, no instruction (`subject`: the word before the verb, "already",
    -- "has", "had", "was", "were" and "just" between them)
    { what = "reports of what was done", words = "cleared gave vectored turned instructed switched disconnected",
      subject = "student trainee instructor he she they i we someone somebody colleague",
      clause = true },
    -- "expect runway 30 left", "expect ILS approach", "expect lower in 10 miles": information for the
    -- pilot's planning, no clearance (lexicon.not_a_clearance), up to the end of its clause ("expect to resume
    -- own navigation to MNR shortly"); an aircraft then "to" after it ("expect IBE3142 to climb to FL200") is the
    -- speaker's expectation of that aircraft, no pilot's planning (`not_aircraft_to`): asked whether it is sent
    -- ("expect to descend and maintain FL120": a level joined by "maintain" straight after the motion expected is
    -- asked, `maintain_joined`; "expect to descend FL100... no, FL90": a correction after a mark corrects what is
    -- expected, `corrected_through`; grammar.lua G:not_simulated)
    { what = "expected clearances", words = "expect expecting", clause = true, not_aircraft_to = true,
      maintain_joined = true, corrected_through = true },
    -- "expedite through FL170": a rate while crossing a level, which squawk does not model
    { what = "expedite instructions", words = "expedite", near = { "through", "passing" } },
    -- "climb FL300 quickly", "descend FL200, expedite", "turn hard left heading 350", "climb rapidly to FL300": how
    -- fast or hard a change is flown, said as its manner (`manner`: G:said_as_manner), which squawk flies at the
    -- aircraft's own rate; the phrase is the word alone, noted and left to its instruction
    { what = "how fast or hard a change is flown", words = "expedite expedited quickly fast hard sharp sharply",
      manner = true },
    -- (and "rapid", "rapidly": a Spanish or Portuguese speaker's "rápido" for quickly, "climb FL270 rapid")
    { what = "how fast or hard a change is flown", words = "rapid rapidly", manner = true },
    -- (and "hurry": "climb FL150, habibi hurry", "descend FL100 hurry up")
    { what = "how fast or hard a change is flown", words = "hurry", manner = true },
    -- "descend FL150 at a good rate", "at your best rate KLM12 climb FL300": the same said of the rate, with no value
    -- (`rate_manner`: G:rate_manner, lexicon.rate_manner), noted from "at" or "with" before it to the rate's word and
    -- the motion it names ("of descent"); a gentler one ("at a slow rate") is asked
    { what = "how fast or hard a change is flown", words = "rate", rate_manner = true },
    -- "turn left heading 170, terrain", "descend FL200 weather", "aua917 terrain!! climb fl190": terrain or weather
    -- named bare beside an instruction (`bare`: G:said_bare), its reason, which squawk does not simulate
    { what = "terrain and weather", words = "terrain weather icing storm storms thunderstorm thunderstorms cloud "
      .. "clouds mountain mountains turbulence", bare = true },
    -- "make a left three sixty", "orbit right": squawk flies no orbits
    { what = "orbits", words = "orbit orbits", takes_time = true },
    { what = "orbits", words = "make do", near = { "sixty", "360", "orbit", "orbits" }, takes_time = true },
    -- "turn around completely, 360 to the right", "a full circle": a turn back onto the same heading
    { what = "orbits", words = "turn turning", near = { "completely", "circle" }, to_end = true },
    { what = "orbits", words = "full", near = { "circle", "360", "sixty", "turn" }, takes_time = true },
    -- (`level_after_place`: a level with its unit said straight after the fix, "hold at KOK 2000ft", is the
    -- level flown there: read as an instruction of its own, G:not_simulated)
    { what = "holding patterns", words = "holding", takes_time = true, level_after_place = true },
    -- (`not_before`: "hold the sim at 30 minutes" holds the simulation, no aircraft; `not_at_time`: nor is "schedule
    -- hold at 00:15:00", a time after "at" or "in", nor "hold" after "schedule")
    { what = "holding patterns", words = "hold",
      near = { "at", "over", "published", "short", "fix", "inbound", "turns", "#waypoint" }, takes_time = true,
      not_before = "@sim", no_value = true, level_after_place = true, not_at_time = true,
      not_after = "schedule sched" },
    { what = "holding patterns", words = "enter", near = { "hold", "holding" }, takes_time = true },
    -- "KL204, hold": said to an aircraft, no pause of the simulation; what follows "then" waits for it
    -- (`no_value`: a value said straight after it, "hold 250 knots", "hold FL150", is kept: G:value_next)
    { what = "holding patterns", words = "hold", after_callsign = true, takes_time = true, no_value = true },
    -- "climb FL300, squawk", "descend FL150 then hold", "turn left heading 200, report", "climb FL300 vectors",
    -- "descend 4000, approach": the word said bare (`bare`: alone in its clause beside an instruction, G:said_bare)
    -- names what squawk does not simulate, beside the instruction flown to an aircraft (said bare before the
    -- instruction, "hold KLM12 climb FL300", a hold may be the simulation's: asked, G:unaccounted)
    { what = "transponder codes", words = "squawk squawking sq squak sqwk sqk", bare = true, after_instruction = true },
    { what = "holding patterns", words = "hold", bare = true, after_instruction = true, takes_time = true },
    { what = "position reports", words = "report reporting", bare = true, after_instruction = true },
    { what = "radar vectors", words = "vectors vectoring vector", bare = true, after_instruction = true },
    -- ("turn left heading 200, traffic": traffic told with no more said)
    { what = "traffic information", words = "traffic", bare = true, after_instruction = true },
    -- ("speed 240, radar": the aircraft told it is seen on radar)
    { what = "radar identification", words = "radar identified", bare = true, after_instruction = true },
    { what = "approach clearances", words = "approach ils rnav rnp vor visual localizer localiser glideslope glidepath "
      .. "land landing takeoff", bare = true, after_instruction = true },
  },
  -- answers that decline a yes/no question ("delete 5 aircraft?")
  no = { "no", "negative", "nope", "don't", "dont", "stop",
         -- (Turkish "hayır", its dotless i taken off as G.lexicon_says reads it)
         "hayir" },
  turn_around = { "around", "opposite", "reverse" },
  -- names said before a value they introduce
  named = { "named", "called" },
  -- a place name's "Saint" said in full or short, each tried as the other in navaid names ("saint prex", ST. PREX)
  saint_forms = { saint = "st", st = "saint" },
  id_words = { "named", "called", "callsign", "id", "registration", "registered" },
  -- words after an airport's name ("Beijing Capital airport")
  -- air traffic units named by no airport or city ("Shanwick", "Scottish"; the rest are the navdata's
  -- airport and city names): a station in the addressing position (G:explained_spans)
  atc_units = { "shanwick", "gander", "scottish", "maastricht", "reykjavik", "santa maria", "new york", "shannon",
      "swanwick", "london", "manchester", "brest", "reims", "langen", "rhein", "karlsruhe", "padova", "bodo",
      "canarias", "moncton", "montreal", "edmonton", "anchorage", "oakland", "sondrestrom" },
  -- (with the kinds of airport said after its name, as "International" is: "Reagan National", "Lakefront Municipal")
  airport_nouns = { "airport", "international", "intl", "airfield", "aerodrome", "national", "natl", "regional", "rgnl",
    "municipal", "muni" },
  -- large airports' IATA codes (names.iata_airports) that are English words typed in lower case, never read as the
  -- code ("send it to sea", "add", "man"; in capitals, "SEA", they are the code)
  iata_words = { "add", "bah", "bog", "bud", "del", "den", "doh", "dub", "ham", "lax", "mad", "man", "sat", "sea",
    "sin", "vie", "dal", "mel", "aus", "str", "pek" },
  -- cities English names otherwise than the navdata, each with the name the navdata gives its one
  -- large airport (its own language's name, or the airport's: "Munich" is MUNCHEN, "Vienna" SCHWECHAT);
  -- cities of several large airports (Rome, Milan, London, Paris) are none of these: a name alone is asked
  city_airports = { munich = "munchen", nuremberg = "nurnberg", cologne = "koln bonn", vienna = "schwechat",
                    prague = "ruzyne", venice = "venezia tessera", lisbon = "lisboa", copenhagen = "kastrup",
                    warsaw = "okecie", berlin = "schonefeld", athens = "eleftherios venizelos", turin = "torino", florence = "firenze",
                    naples = "capodichino", budapest = "ferihegy", gothenburg = "landvetter",
                    amsterdam = "schiphol", oslo = "gardermoen", bergen = "flesland", stavanger = "sola",
                    trondheim = "vaernes",
                    -- (Italian cities whose airport the navdata names after the place beside it: Verona's
                    -- VILLAFRANCA, its small VERONA BOSCOMANTICO aside; Trento's MATTARELLO; Trieste's RONCHI)
                    verona = "villafranca", trento = "mattarello", trieste = "ronchi dei legionari",
                    genoa = "genova sestri",
                    -- (an airport's own name the navdata does not give, said with its city or alone)
                    ["el prat"] = "barcelona", ["barcelona el prat"] = "barcelona",
                    delhi = "indira gandhi", ["new delhi"] = "indira gandhi", mumbai = "chhatrapati shivaji",
                    bombay = "chhatrapati shivaji", kolkata = "netaji subhash chandra bose",
                    calcutta = "netaji subhash chandra bose", hyderabad = "rajiv gandhi",
                    bangalore = "bengaluru", bengaluru = "bengaluru", karachi = "jinnah",
                    lahore = "allama iqbal", kathmandu = "tribhuvan", ["addis ababa"] = "bole",
                    ["dar es salaam"] = "mwalimu julius k nyerere", tashkent = "yuzhny", yerevan = "zvartnots",
                    baku = "heydar aliyev", ["st petersburg"] = "pulkovo", ["saint petersburg"] = "pulkovo",
                    yekaterinburg = "koltsovo", novosibirsk = "tolmachevo", samara = "kurumoch", bishkek = "manas",
                    kyiv = "boryspil intl", kiev = "boryspil intl",
                    -- (Turkey and Cyprus: the cities of one large airport the navdata names otherwise, "Izmir" its
                    -- ADNAN MENDERES beside the IZMIR VOR; Istanbul, of two, is none of these)
                    izmir = "adnan menderes", ankara = "esenboga", bodrum = "milas bodrum", gaziantep = "oguzeli",
                    isparta = "suleyman demirel", paphos = "pafos intl", cappadocia = "kapadokya",
                    nevsehir = "kapadokya",
                    -- (the Caribbean, Central America and Mexico: the stations named by their city, "Havana",
                    -- "Kingston", whose airport the navdata names otherwise)
                    havana = "jose marti", habana = "jose marti", ["la habana"] = "jose marti",
                    ["mexico city"] = "licenciado benito juarez", guadalajara = "don miguel hidalgo",
                    monterrey = "general mariano escobedo", tegucigalpa = "toncontin",
                    ["santo domingo"] = "las americas", kingston = "norman manley", ["montego bay"] = "sangster",
                    nassau = "lynden pindling", ["port of spain"] = "piarco", ["grand cayman"] = "owen roberts",
                    ["panama city"] = "tocumen", bogota = "eldorado", ["port-au-prince"] = "toussaint louverture",
                    -- (Central and South America by the city's name in English or Spanish, and Bogotá's airport
                    -- said in two words, "El Dorado", as the navdata's ELDORADO)
                    guatemala = "la aurora", ["guatemala city"] = "la aurora", ["ciudad de guatemala"] = "la aurora",
                    ["ciudad de mexico"] = "licenciado benito juarez", ["san salvador"] = "el salvador",
                    cali = "alfonso bonilla aragon", guayaquil = "jose joaquin de olmedo",
                    barranquilla = "ernesto cortissoz", ["el dorado"] = "eldorado",
                    curacao = "hato", aruba = "reina beatrix", bonaire = "flamingo",
                    -- (West and Central Africa: capitals and hubs whose one airport the navdata names otherwise)
                    lagos = "murtala muhammed", abuja = "nnamdi azikiwe", kano = "mallam aminu", accra = "kotoka",
                    lome = "gnassingbe eyadema", abidjan = "abidjan felix houphouet boigny", dakar = "leopold sedar senghor",
                    kinshasa = "ndjili", brazzaville = "maya maya", luanda = "luanda 4 de fevereiro",
                    niamey = "diori hamani", cotonou = "cadjehoun", bamako = "senou", libreville = "leon m ba",
                    yaounde = "yaounde nsimalen", monrovia = "monrovia roberts", freetown = "freetown lungi",
                    ["n'djamena"] = "ndjamena hassan djamous", ndjamena = "ndjamena hassan djamous",
                    -- (Belgium, Switzerland and New England: the city's airport named after a place beside it;
                    -- Brussels's national airport, its BRUSSELS SOUTH being Charleroi's)
                    charleroi = "brussels south", ostend = "oostende", antwerp = "deurne", basel = "bale mulhouse",
                    brussels = "brussels natl", zaventem = "brussels natl",
                    boston = "general edward lawrence logan", ["boston logan"] = "general edward lawrence logan",
                    -- (the US: the city's airport named after a person, and Washington's National by its
                    -- namesake; Cyprus's Paphos as the navdata spells it)
                    milwaukee = "general mitchell", ["reagan national"] = "ronald reagan washington natl",
                    ["ronald reagan"] = "ronald reagan washington natl", paphos = "pafos",
                    -- (California: the city's airport named after a person)
                    burbank = "bob hope",
                    -- (South-East Asia: cities whose one large airport the navdata names after a person, a
                    -- district or the island)
                    manila = "ninoy aquino intl", jakarta = "soekarno hatta intl", hanoi = "noibai intl",
                    saigon = "tansonnhat intl", surabaya = "juanda", denpasar = "bali intl",
                    -- (southern France: the city's airport named after the village beside it)
                    perpignan = "rivesaltes", carcassonne = "salvaza",
                    -- (transatlantic destinations: the city's or island's one large or international airport named
                    -- after a person; Toronto's other, CITY CENTRE, is a small field)
                    toronto = "lester b pearson", antigua = "v c bird", ["saint maarten"] = "princess juliana",
                    ["st maarten"] = "princess juliana", ["sint maarten"] = "princess juliana",
                    -- (Japan: the airport known by its district, which the navdata names after its city)
                    -- (the Gulf and the Levant: the capital's or city's one large airport the navdata names after a
                    -- king or queen, or by its old name, Muscat's SEEB)
                    muscat = "seeb intl", riyadh = "king khaled intl", jeddah = "king abdulaziz intl",
                    dammam = "king fahd intl", amman = "queen alia intl",
                    haneda = "tokyo intl", ["tokyo haneda"] = "tokyo intl", itami = "osaka intl",
                    ["osaka itami"] = "osaka intl",
                    -- (the Middle East: the city's one large airport named after a person, its name said after
                    -- the city's too, "Jeddah King Abdulaziz"; Amman's MARKA is a medium field)
                    amman = "queen alia", ["amman queen alia"] = "queen alia", jeddah = "king abdulaziz",
                    ["jeddah king abdulaziz"] = "king abdulaziz", ["amman marka"] = "marka" },
  -- a city's airline airport by the city's name, where navdata gives the city other large fields nearby (beside
  -- its navaid, or holding its name): "Atlanta airport" is KATL, not DeKalb-Peachtree KPDK; "Baltimore airport" is
  -- KBWI, not Fort Meade's 3000 ft TIPTON. Read only when that airport is among the candidates found; a city of
  -- several airline airports (Chicago, London, Montreal) is not listed and stays asked.
  main_airports = { atlanta = "KATL", baltimore = "KBWI", milwaukee = "KMKE", providence = "KPVD" },
  -- prepositions before a place named by its name ("at Barajas", "over Schiphol")
  place_words = { "at", "over", "above", "near", "from", "overhead" },
  -- A city or airport named to describe an aircraft or airspace, no place instructed: said before one of
  -- `before` ("a Charlotte arrival", "the Madrid TMA", "Barcelona ACC"), or after one of `after` said straight
  -- after one of `leads` ("the arrival into Atlanta", "inbound to Lisbon", "bound for Vigo"); a place an aircraft
  -- comes from after its callsign ("DLH4AX inbound from Vigo, ...") is no description here (it is asked)
  described_places = {
    before = { "arrival", "arrivals", "departures", "inbound", "inbounds", "outbound", "tma", "acc", "fir", "cta",
        "uac", "sector", "airspace", "flow", "stream", "push", "bank" },
    after = { "into", "for", "to" },
    leads = { "arrival", "arrivals", "inbound", "arriving", "bound", "flight", "flights", "departing" },
    -- where an aircraft comes from said in a relative clause that identifies it, no origin set ("the Easy that's
    -- just departed Luton, Easy 55KJ, ..."): a word of `departs` after one of `relatives`, words of `relative_fill`
    -- between (G:relative_departure)
    departs = { "departed", "departing", "left", "leaving" },
    -- the same said with no place, ending its clause straight after the aircraft or its relative word ("the Southwest
    -- that just took off, climb it ...", "the United departing, climb ..."): a description, no origin set
    -- (G:departure_described)
    departs_alone = { "departed", "departing", "took off", "taken off", "lifted off" },
    relatives = { "that", "that's", "thats", "which", "who", "who's", "whos" },
    relative_fill = { "just", "has", "have", "had", "is", "was", "now", "recently", "only", "since" },
    -- the same told of the aircraft as a pronoun, "just" between ("It has just departed Schiphol in my story"): the
    -- recent past narrated, no origin set
    narrated = { "it", "it's", "its", "he", "he's", "she", "she's" },
    -- where an aircraft flies to, from or over, said straight after the aircraft opening its clause, the place
    -- closing it at a comma, to identify it, no place instructed ("the Ryanair out of Cork, up to 17 thousand",
    -- "the Loganair going into Derry, bring it down", "the Aer Lingus coming over Wales, go direct VATRY"): only
    -- words of `moving` between the aircraft and the place (G:moving_place), one to four of them, the first one of
    -- `moving_leads` ("the Ryanair to Cork," may send it there: asked)
    moving_leads = { "going", "coming", "heading", "headed", "flying", "routing", "bound", "inbound", "outbound",
        "out", "off", "over", "from" },
    moving = { "going", "coming", "heading", "headed", "flying", "routing", "out", "of", "off", "over", "into", "in",
        "to", "down", "up", "toward", "towards", "across", "from", "for", "the", "bound", "inbound", "outbound" },
    -- regions and countries said as such a place, lower case, that no airport is named after
    regions = { "scotland", "wales", "england", "ireland", "northern ireland", "isle of man", "the isle of man",
        "france", "spain", "iceland", "norway", "cornwall", "the continent" } },
  -- kinds of navaid, said beside a navaid's name ("the Pampus VOR, PAM")
  navaid_kinds = { "vor", "ndb", "dme", "vortac", "navaid", "beacon" },
  -- words that put a place's ident after its name ("Thermal, that is TRM"), and the lower-case words inside a
  -- place's name ("Truth or Consequences") (G.named_idents)
  apposition = { "that is", "that's", "i.e.", "ie", "namely" },
  place_name_joiners = { "or", "of" },
  -- a condition on a place said beside value instructions, which read no place (G:passage_left): a word of
  -- `passage` opens one whatever follows ("passing the beacon", "abeam it"), one of `passage_at` before a word of
  -- `passage_nouns`, navaid_kinds or airport_nouns ("over the VOR", "at the marker")
  passage = { "passing", "passed", "abeam", "past", "approaching", "reaching", "overhead", "leaving" },
  passage_at = { "over", "at", "by" },
  passage_nouns = { "fix", "waypoint", "marker", "threshold", "station", "border", "boundary" },
  -- ("heading 200, then continue on course", "... back on track"): a word of going on said beside value
  -- instructions with no instruction of its own in its clause (G:going_on_left); "back" only before "on"
  going_on = { "continue", "resume", "back" },
  -- the navdata types a kind said after a navaid's name means ("the Eelde VOR" is EEL, not the NDB SO)
  navaid_types = { vor = "VOR TACAN", vortac = "VOR TACAN", ndb = "NDB", dme = "DME" },
  -- DEFWPT's waypoint types, said after "as" or "type" ("define DELTA at 51.9 4.1 as a fix")
  waypoint_types = { fix = "FIX", vor = "VOR", dme = "DME", ndb = "NDB" },
  -- pronouns: never read as a name ("add it to the route" is no waypoint "IT")
  pronouns = { it = true, its = true, him = true, her = true, them = true, they = true },
  -- words skipped before a spoken waypoint name
  before_name = { "to", "the", "ah", "uh", "direct", "via", "now", "point" },
  -- words that place a waypoint by its order on a route ("the next waypoint", "the last fix"): no name of their own,
  -- so never a waypoint's name heard where nothing is known to match it (handlers_other m:spoken_name)
  route_ordinals = { "next", "following", "subsequent", "last", "final", "first", "previous", "preceding" },
  -- the nationality letter and first letter of registrations said without that nationality letter (Canada's
  -- C-F..., C-G..., C-I...: "Golf Kilo Whiskey Alpha" is C-GKWA)
  nationless_registrations = { "CF", "CG", "CI" },
  -- the nationality marks of two letters of registrations of five letters in all (OO-XYZ, PH-ABC), one string so
  -- that no mark is a word squawk knows: a registration typed in lower case beside a new aircraft's type ("new
  -- c172 ooxyz ...") is its callsign when it opens with one (one letter, D-EABC, opens too many words)
  registration_marks = "CS EC EI HA HB LN LX OE OH OK OM OO OY PH SE SP SX TC TF VH YR ZK ZS",
  -- words that lead a waypoint's name spelled again after it ("direct SAMUD, spelling Sierra Alpha ...", "I spell")
  spelling_leads = { "spelling", "spelled", "spelt", "spell", "i" },
  -- digits said as words, the radiotelephony forms ("tree", "fower", "fife", "niner") included: word -> digit
  digit_words = { zero = "0", one = "1", two = "2", three = "3", tree = "3", four = "4", fower = "4", five = "5",
                  fife = "5", six = "6", seven = "7", eight = "8", nine = "9", niner = "9" },
  -- the phonetic alphabet (spelled waypoint names)
  phonetic = {
    alpha = "A", alfa = "A", bravo = "B", charlie = "C", charly = "C", delta = "D", echo = "E", foxtrot = "F",
    foxtrott = "F", golf = "G",
    hotel = "H", india = "I", juliet = "J", juliett = "J", juliette = "J", kilo = "K", lima = "L", mike = "M",
    november = "N", oscar = "O", papa = "P", quebec = "Q", romeo = "R", sierra = "S", tango = "T",
    uniform = "U", victor = "V", whiskey = "W", whisky = "W", xray = "X", yankee = "Y", zulu = "Z",
    -- letters said by their English names where that name is no everyday word ("five kay alfa")
    kay = "K", aitch = "H", dee = "D", vee = "V", zed = "Z",
    -- the older alphabet's word for F, still said by some controllers ("Virgin two five fox")
    fox = "F",
    -- (November as a non-rhotic speaker says it and a recogniser writes it: "ryanair eight novemba bravo")
    novemba = "N",
  },
  -- a conflict-detection or run setting changed by an amount or a factor of its value now ("bump the lookahead up a
  -- minute", "halve the zone", "make it twice as fast", "zone height plus 200 feet"; grammar.lua's
  -- G.relative_settings): the setting's names -> its command; the factors; the words of a change up or down; the
  -- units of an amount -> { command = its size in the command's unit } (a bare number is in the command's unit)
  relative_settings = {
    names = { ["lookahead time"] = "DTLOOK", ["look-ahead time"] = "DTLOOK", ["look ahead time"] = "DTLOOK",
              lookahead = "DTLOOK", ["look-ahead"] = "DTLOOK", ["look ahead"] = "DTLOOK", dtlook = "DTLOOK",
              ["zone height"] = "ZONEDH", ["zone half-height"] = "ZONEDH", ["zone half height"] = "ZONEDH",
              zonedh = "ZONEDH", ["zone radius"] = "ZONER", ["protected zone"] = "ZONER", zone = "ZONER",
              zoner = "ZONER", ["sim speed"] = "DTMULT", ["sim rate"] = "DTMULT", ["simulation speed"] = "DTMULT",
              ["simulation rate"] = "DTMULT", ["speed of the sim"] = "DTMULT", ["speed of the simulation"] = "DTMULT",
              ["time multiplier"] = "DTMULT", dtmult = "DTMULT", dh = "ZONEDH", ["zone dh"] = "ZONEDH",
              ["pz height"] = "ZONEDH", ["pz half height"] = "ZONEDH", ["pz half-height"] = "ZONEDH",
              ["half height"] = "ZONEDH", ["half-height"] = "ZONEDH", ["pz radius"] = "ZONER", rpz = "ZONER",
              radius = "ZONER", ["vertical margin"] = "RFACV", ["vert margin"] = "RFACV", rfacv = "RFACV",
              ["vertical reso factor"] = "RFACV", ["vertical resolution factor"] = "RFACV",
              ["horizontal margin"] = "RFACH", ["horiz margin"] = "RFACH", ["hor margin"] = "RFACH", rfach = "RFACH",
              ["horizontal reso factor"] = "RFACH", ["horiz reso factor"] = "RFACH",
              ["horizontal resolution factor"] = "RFACH", ["vertical zone"] = "ZONEDH",
              pz = "ZONER", hpz = "ZONEDH", ["vertical pz"] = "ZONEDH", ["vertical protected zone"] = "ZONEDH",
              ["vertical separation"] = "ZONEDH", ["horizontal separation"] = "ZONER", ["horizontal pz"] = "ZONER",
              ["horizontal protected zone"] = "ZONER", ["horizontal zone"] = "ZONER",
              ["vertical reso safety factor"] = "RFACV", ["vertical resolution safety factor"] = "RFACV",
              ["horizontal reso safety factor"] = "RFACH", ["horizontal resolution safety factor"] = "RFACH",
              ["vertical resolution margin"] = "RFACV", ["vertical reso margin"] = "RFACV",
              ["horizontal resolution margin"] = "RFACH", ["horizontal reso margin"] = "RFACH" },
    -- the names of the zone's radius, and the words that name its height with a name of the zone alone
    radius_names = { ["zone radius"] = true, ["pz radius"] = true, rpz = true, radius = true, zoner = true,
                     ["horizontal separation"] = true, ["horizontal pz"] = true, ["horizontal protected zone"] = true,
                     ["horizontal zone"] = true },
    vertical = { vertical = true, vert = true, vertically = true, height = true },
    -- a share said in words after its number ("25 percent", "20 pct"); the arrows from the value now to another
    percent = { percent = true, pct = true, ["%"] = true },
    factors = { double = 2, triple = 3, quadruple = 4, halve = 0.5, ["half the"] = 0.5, ["in half"] = 0.5,
                doubled = 2, tripled = 3, halved = 0.5, quartered = 0.25,
                -- (a share "of what it is" or "of that", the value now; "the vertical half of the zone" is none)
                ["three quarters of what"] = 0.75, ["two thirds of what"] = 2 / 3, ["half of what"] = 0.5,
                ["a third of what"] = 1 / 3, ["a quarter of what"] = 0.25, ["a fifth of what"] = 0.2,
                ["a tenth of what"] = 0.1, ["half of that"] = 0.5, ["a third of that"] = 1 / 3,
                ["a quarter of that"] = 0.25, ["a fifth of that"] = 0.2, ["a tenth of that"] = 0.1,
                ["twice as fast"] = 2, ["three times as fast"] = 3, ["four times as fast"] = 4, ["half as fast"] = 0.5 },
    -- shares of the value now, said after "a" ("up by a quarter", "down a third")
    shares = { quarter = 0.25, third = 1 / 3, fifth = 0.2 },
    -- words before a value that make it the value set ("to times 10", "on 6 NM", "to a 3 mile radius"): true; words
    -- that may stand between: false
    before_value = { to = true, on = true, at = true, of = true, is = true, be = true, was = true, were = true,
                     ["="] = true, times = false,
                     a = false, an = false, factor = false, x = false, about = false, around = false },
    -- (the run's rate: named by these with a word of its speed, "slow the sim down by half")
    run_words = { sim = true, simulation = true },
    run_speed = { slow = true, slower = true, fast = true, faster = true, speed = true, quicker = true },
    -- (verbs of running that open a clause of their own, "resume the sim at ...", "run the sim for 5 minutes fast":
    -- the grammar's to read)
    run_kept = { run = true, resume = true, continue = true, start = true, go = true, unpause = true },
    -- (a clause's clock command beside a setting's change, "pause rpz x2", "op ff dtmult x3": the clause is no change
    -- of one setting alone; the grammar's to read)
    clock_words = { op = true, hold = true, pause = true, freeze = true, unpause = true, ff = true },
    up = { up = true, raise = true, increase = true, extend = true, add = true, plus = true, out = true,
           bump = true, lengthen = true, widen = true, grow = true, bigger = true, larger = true, longer = true,
           wider = true, higher = true, more = true, greater = true },
    down = { down = true, lower = true, reduce = true, decrease = true, cut = true, minus = true, shrink = true,
             shorten = true, tighten = true, off = true, smaller = true, shorter = true, narrower = true,
             tighter = true, less = true },
    units = { minute = { DTLOOK = 60 }, minutes = { DTLOOK = 60 }, min = { DTLOOK = 60 }, mins = { DTLOOK = 60 },
              second = { DTLOOK = 1 }, seconds = { DTLOOK = 1 }, sec = { DTLOOK = 1 }, secs = { DTLOOK = 1 },
              s = { DTLOOK = 1 }, mile = { ZONER = 1 }, miles = { ZONER = 1 }, nm = { ZONER = 1 },
              nmi = { ZONER = 1 }, feet = { ZONEDH = 1 }, foot = { ZONEDH = 1 }, ft = { ZONEDH = 1 } },
  },
  -- an arrow from a value now to the value wanted ("rpz 5 -> 6", grammar.lua's G.arrows); the units and switch
  -- positions a value now may be said with
  arrows = { "->", "\u{2192}", "=>" },
  arrow_units = { s = true, sec = true, secs = true, second = true, seconds = true, min = true, mins = true,
                  minute = true, minutes = true, nm = true, ft = true, feet = true, kt = true, kts = true,
                  knots = true, fpm = true, hz = true, ["%"] = true, m = true, km = true },
  arrow_states = { on = true, off = true, none = true, ["v/s"] = true, vs = true, mvp = true, pastcpa = true,
                   statebased = true, class = true, openap = true },
  -- the words naming a setting in a clause with an arrow
  arrow_setting_words = { rpz = true, pz = true, hpz = true, dh = true, zone = true, zoner = true, zonedh = true, radius = true,
                          lookahead = true, ["look-ahead"] = true, dtlook = true, dtmult = true, rfach = true,
                          rfacv = true, rmethv = true, reso = true, asas = true, cd = true, detection = true,
                          resolution = true, sim = true, simulation = true, half = true, height = true,
                          trail = true, trails = true, noise = true, vnav = true, lnav = true, resnav = true,
                          perf = true, cdmethod = true, dt = true },
  -- the words of a condition and of moving before an arrow: then its "then" ("passing fl100 -> 220 kt") or its "to"
  -- ("mv TRA6021 -> 52.5 4.4")
  arrow_conditions = { passing = true, at = true, reaching = true, when = true, once = true, after = true,
                       over = true, abeam = true },
  arrow_moves = { mv = true, move = true, put = true, teleport = true, place = true },
  -- an aircraft's value names before a value now and an arrow ("spd 280 -> 300", "vs 1000 → 2000", "M.78 → M.80")
  arrow_value_names = { spd = true, speed = true, vs = true, mach = true, m = true, bank = true },
  -- verbs opening a clause said to come first ("climb FL200, speed 250 first", grammar.lua's G.first_said_first)
  first_openers = { climb = true, descend = true, turn = true, reduce = true, increase = true, heading = true, set = true,
                    delete = true, create = true, move = true, pause = true, hold = true, add = true, direct = true },
  -- clock commands after an arrow ("ff 10 min → pause"): the arrow is "then"
  arrow_then = { pause = true, hold = true, op = true, resume = true, run = true, freeze = true },
  -- a level's names before two bare levels and an arrow ("alt 310 -> 270": FL310 to FL270)
  arrow_level_names = { alt = true, altitude = true, lvl = true, level = true },
  -- a clause keeping settings as they are ("cd stays", "rfacv unchanged": grammar.lua's G.kept_settings): the words
  -- that may name them, and the words of keeping
  kept_settings = { names = { "cd", "asas", "reso", "detection", "resolution", "conflict", "mvp", "rmethv", "rfach",
                              "rfacv", "rfac", "vertical", "horizontal", "the", "rest", "everything", "else", "other",
                              "settings", "factor", "factors", "method", "lookahead", "zone", "radius", "height" },
                    kept = { "stays", "unchanged", "untouched", "remains", "kept", "as-is" } },
  -- the words after which "A" and three digits is an altitude in hundreds of feet ("descend A090", grammar.lua's
  -- G.area_altitudes)
  area_altitude_after = { climb = true, climbing = true, descend = true, descending = true, desc = true, des = true,
                          clb = true, maintain = true, to = true, passing = true, pass = true, reaching = true,
                          reach = true, leaving = true, altitude = true, at = true, cleared = true, recleared = true },
  -- the English names of letters that are everyday words or no words ("kay el em": KLM), read as letters only where
  -- three in a row before a flight number open the id of an aircraft flying (grammar.lua's G.letter_name_airlines)
  letter_names = { ay = "A", bee = "B", see = "C", cee = "C", ee = "E", ef = "F", eff = "F", gee = "G", eye = "I",
                   jay = "J", el = "L", ell = "L", em = "M", en = "N", oh = "O", pee = "P", cue = "Q", ar = "R",
                   ess = "S", tee = "T", you = "U", ex = "X", why = "Y", zee = "Z" },
  -- what speech recognition writes for an instruction word that sounds alike
  -- ("the send flight level one niner zero", "turn write heading 040",
  -- "head in one one zero", "two six zero nots", "descend two flight level").
  -- A heard form is that word ONLY where the word is expected: `before` (the
  -- next word is one of these; "#number" any number, digits or number words),
  -- `after` (the word before it is one of these), or `between` (both: after
  -- one of between[1] and before one of between[2]), or `closed_after` (after one of these, a mark or the
  -- request's end closing the form: "when reach, Mach .79"); never after a word of
  -- `not_after` (a name the heard form ends: "red cap 712" is AirAsia). Anywhere else it stays
  -- what it is ("write the heading down", "head into the wind", "the send
  -- button", "climb two four thousand").
  -- a protocol's verbs in the third person after a condition or a mark ("..., when passing FL100, accelerates to
  -- 280 knots", "passing FL120, it accelerates to 300 knots"): the instruction's verb (grammar.lua G.third_person)
  third_person = { accelerates = "accelerate", decelerates = "decelerate", slows = "slow", reduces = "reduce",
    increases = "increase", expedites = "expedite", proceeds = "proceed", flies = "fly", turns = "turn",
    maintains = "maintain" },
  -- an experimenter's protocol in the passive voice ("Easy 45GH is moved to 52.35 N 4.40 E", "the route of KLM1234
  -- is displayed", "SUGOL is added to the route of TRA5KD", "ten aircraft are then generated"): the participle after
  -- "is" or "are" (and any of `adverbs`) is the instruction's verb, said before its subject (grammar.lua
  -- G.passive_voice); one of `told` and "to" leave the subject before the instruction; a participle not listed
  -- ("cleared", "transferred") leaves the sentence as said
  passive = {
    participles = { moved = "move", displayed = "display", shown = "show", printed = "print", listed = "list",
      added = "add", appended = "append", inserted = "insert", assigned = "assign", set = "set",
      increased = "increase", decreased = "decrease", reduced = "reduce", raised = "raise", lowered = "lower",
      ["fast-forwarded"] = "fast-forward", generated = "generate", created = "create", spawned = "spawn",
      deleted = "delete", removed = "remove", written = "write", echoed = "echo", limited = "limit",
      defined = "define", paused = "pause", frozen = "freeze", resumed = "resume", enabled = "enable",
      disabled = "disable", activated = "activate", deactivated = "deactivate", changed = "change",
      coloured = "colour", colored = "color", queried = "query", seeded = "seed", taken = "take" },
    -- ("KLM1234 is then instructed to turn right ...": the aircraft told, the instruction after "to" its own)
    told = { "instructed", "told", "ordered", "asked" },
    -- words that make the clause a question, a condition or a reason, never a subject ("which time step is set",
    -- "after the speed is reduced to 250 knots, descend", "so that aircraft leaving the sector are removed")
    not_subject = { "which", "what", "how", "whether", "where", "when", "whenever", "once", "after", "before", "until",
      "till", "if", "unless", "that", "so", "as", "because", "since", "while", "passing", "reaching" },
    adverbs = { "then", "now", "first", "also", "subsequently", "finally", "next", "again", "immediately" },
  },
  -- English words as a recogniser writes them from a German or Swiss accent ("flight lefel two sree tsero", "turn
  -- left hetting tsero sree fife", "fife tousand feet") or a Spanish one ("flight leber one two sero", "headin",
  -- "espeed", "seben"): no word of English, each read as the word it is wherever it stands (typed in capitals, a
  -- name, it stays as typed; grammar.lua G.accented)
  -- accented words that typed with a capital, or closing an airline's telephony ("air van"), are a name's ("Van
  -- Nuys"), never the accent's word
  accented_names = { van = true },
  accented = { tsero = "zero", sree = "three", zree = "three", sefen = "seven", tousand = "thousand",
    sousand = "thousand", lefel = "level", hetting = "heading", hedding = "heading", sirty = "thirty",
    tventy = "twenty", kebec = "quebec", yuliett = "juliett", tsulu = "zulu",
    sero = "zero", seben = "seven", leber = "level", lebel = "level", headin = "heading", espeed = "speed",
    tirty = "thirty", altitud = "altitude", tousan = "thousand",
    -- (French: "eading", "sen" and "zen" for "then"; Italian and Greek: "eding", "fligh level")
    eading = "heading", sen = "then", zen = "then", eding = "heading", fligh = "flight",
    -- (German: "fligt level")
    fligt = "flight",
    -- (Indian and Sri Lankan: "wan" for one, "nayner", "clime", "fly-level")
    wan = "one", nayner = "niner", clime = "climb", ["fly-level"] = "flight level",
    -- (Portuguese and Brazilian: "ninner")
    ninner = "niner",
    -- (Japanese and Korean: l for r and p for f, a vowel after a closing consonant: "turn reft", "leduce", "pive",
    -- "sebun", "sixu", "notto", "bertical")
    reft = "left", leduce = "reduce", pive = "five", sebun = "seven", sixu = "six", notto = "knots",
    bertical = "vertical",
    -- (Thai and Vietnamese: a final consonant dropped or added, "descen", "lef", "righ", "direc", "wha", "fas", "fo"
    -- for four, "fly leven" for flight level)
    descen = "descend", lef = "left", righ = "right", direc = "direct", wha = "what", fas = "fast", fo = "four",
    leven = "level",
    -- ("desen", "tuhn", "leveo", "thousan", "fie" and "fai" for five, "confli"; a /p/ said for /f/ by a Korean
    -- speaker, "pactor", "pipty", is grammar.lua's G.p_said_f)
    desen = "descend", tuhn = "turn", leveo = "level", thousan = "thousand", fie = "five", fai = "five",
    confli = "conflict",
    -- (Korean: "jero" for zero; Polish: "derect")
    jero = "zero", derect = "direct",
    -- (Arabic: "disend"; a /p/ said /b/, "blease", "broceed", is grammar.lua's G.p_said_b)
    disend = "descend",
    -- (Turkish and Persian: a /v/ said /w/, "flight lewel")
    lewel = "level",
    -- (Japanese: l for r, "crimb", "loute", "untir", "contror", "rateral", "leady"; a vowel after a closing consonant,
    -- "thousando", "hundredo", and after an instruction's word, grammar.lua's G.vowel_after: "descendo", "speedo")
    crimb = "climb", loute = "route", untir = "until", contror = "control", rateral = "lateral", leady = "ready",
    thousando = "thousand", hundredo = "hundred",
    -- (French: the h unsaid and th said z or s, "undred", "otel", "wiz", "nort"; "spid", "nots", "turne")
    undred = "hundred", otel = "hotel", wiz = "with", nort = "north", spid = "speed", nots = "knots", turne = "turn",
    -- (Brazilian Portuguese: a final t said "chi", a t before e said "ch", a vowel after a closing consonant:
    -- "turn lefchi", "righchi", "direchi", "flighchi level", "the rouchi", "altichude", "simulachion", "chen minutes",
    -- "descendee", "two hundredy"; "ligue" and "desligue", the verbs of switching on and off)
    lefchi = "left", righchi = "right", direchi = "direct", flighchi = "flight", fliche = "flight", rouchi = "route",
    altichude = "altitude", simulachion = "simulation", chen = "ten", descendee = "descend", hundredy = "hundred",
    ligue = "switch on", desligue = "switch off",
    -- (Romanian, Hungarian, Bulgarian, Serbian and Croatian: "flait level", "flai heading", "flaiing", "redjuce",
    -- "sevendy", "vat is your heading"; a "v" for "w", a "k" for "c", a letter written twice and "t" for "th" are
    -- grammar.lua's G.letters_swapped)
    flait = "flight", flai = "fly", flaiing = "flying", redjuce = "reduce", sevendy = "seventy", vat = "what",
    -- (Mandarin: a final consonant dropped, "crim" for climb, "hol" for hold, "frite" for flight; "l" and "r"
    -- swapped in longer words is grammar.lua's G.letters_swapped)
    crim = "climb", hol = "hold", frite = "flight",
    -- (Indonesian: an /f/ said /p/ and a final consonant dropped, "turn lep", "lept", "pligt level"; "pive", "pour"
    -- and "porward" are grammar.lua's G.p_said_f)
    lep = "left", lept = "left", pligt = "flight",
    -- (Pakistani and Bangladeshi: "turn lepht", "fowerty fife"; "wector", "estop" and "espeed" are grammar.lua's
    -- G.letters_swapped)
    lepht = "left", fowerty = "forty",
    -- (Hebrew: vowels shortened, "flite levl", "hedin"; a guttural r written "kh" is grammar.lua's G.letters_swapped)
    flite = "flight", levl = "level", hedin = "heading",
    -- (Cantonese: a final consonant dropped from a digit, "fi", "eigh"; Scottish and Northern Irish: "headin", "flight
    -- leve", "doon", "thoosand", "hunner", "tae", "oot")
    fi = "five", eigh = "eight", leve = "level", doon = "down", thoosand = "thousand",
    hunner = "hundred", tae = "to", oot = "out", contac = "contact", ["fo-ty"] = "forty", foty = "forty",
    -- (Korean: an /f/ said /p/, "l" said "r" and a vowel after: "prright level", "pright", "pry heading", "turn repto")
    prright = "flight", pright = "flight", pry = "fly", repto = "left",
    -- (French, Spanish and Portuguese: the sign said in the speaker's language, "vertical speed moins one thousand";
    -- French: the h unsaid, "eading")
    moins = "minus", menos = "minus", ["'eading"] = "heading", ["'old"] = "hold", zis = "this",
    ["'undred"] = "hundred",
    -- (Finnish, Estonian, Latvian and Lithuanian: "trect", "teegrees", "rigt", "minut", "kebec"; a "d" said "t", a
    -- "b" said "p" and a long "ee" written "ii" are grammar.lua's G.letters_swapped)
    trect = "direct", teegrees = "degrees", rigt = "right", minut = "minute",
    -- (Swedish, Norwegian and Danish: "klime", "rait", "heding", "dissend", "wiskey", "shuttel", "pappa", "fourty",
    -- "plis", "jes", "okej"; the VOR said "wor"; a "w" for a "v", "sewen", "wektor", is grammar.lua's G.letters_swapped)
    klime = "climb", rait = "right", heding = "heading", dissend = "descend", wiskey = "whiskey", shuttel = "shuttle",
    pappa = "papa", fourty = "forty", plis = "please", jes = "yes", okej = "okay", wor = "vor",
    -- (Caribbean English: a final consonant dropped and vowels shifted, "dissen", "mentain", "lev'l", "heigh",
    -- "conflic", "wha's yuh speed")
    dissen = "descend", mentain = "maintain", ["lev'l"] = "level", heigh = "height", conflic = "conflict",
    ["wha's"] = "what's", ["wha'"] = "what", dere = "there", dat = "that", den = "then",
    -- (Georgian, Armenian and Azerbaijani: "ad a vaypoint", "mov to"; a vowel between two opening consonants and "kh"
    -- for "h" are grammar.lua's G.letters_swapped)
    ad = "add", mov = "move",
    -- (Italian: "attiva conflict detection", "ferma la simulazione"; a vowel after a closing consonant, "speeda",
    -- "fasta forwarda", is grammar.lua's G.vowel_after)
    attiva = "activate", ferma = "stop", simulazione = "simulation", forwarda = "forward",
    -- (Irish: "haddin", "yer route", "wit mvp", "not less tan", "good evenin"; "th" said "t", "tree", "tirty", is read
    -- with the numbers)
    haddin = "heading", haddn = "heading", yer = "your", wit = "with", tan = "than", evenin = "evening",
    mornin = "morning",
    -- (Burmese, Khmer and Lao: a closing consonant unsaid, "descen", "spee", "clai", "tunlef", "kno" ("fli level" is
    -- heard_as's; "tun" stays, TUN a navaid);
    -- "r" said "l" for Lao, "tlee", "zelo", "leduce", is grammar.lua's G.letters_swapped; "fai", "fo", "nai" for
    -- five, four and nine)
    spee = "speed", kno = "knots", altitu = "altitude", rou = "route", dele = "delete",
    dilete = "delete", crea = "create", aircraf = "aircraft", waypoin = "waypoint", poin = "point",
    dilec = "direct", airpor = "airport", fass = "fast", forwar = "forward", foward = "forward",
    lai = "right", clai = "climb", passin = "passing", afta = "after",
    maintai = "maintain", multiplie = "multiplier", resolusion = "resolution", correcson = "correction",
    destinason = "destination", swi = "switch", doin = "doing", easten = "eastern", aili = "airline",
    hunde = "hundred", foe = "four", nai = "nine",
    tunlef = "turn left", tunlai = "turn right", fee = "feet", posison = "position", simulason = "simulation",
    frequensy = "frequency", expedi = "expedite", ahea = "ahead", rada = "radar", dis = "this", hou = "hour",
    -- (Mongolian and Kazakh, a recogniser spelling English as it sounds: "ayt", "nayn", "fayv", "wan", "ziro",
    -- "flaytlebel", "dessend", "reyt", "heding", "spid", "kreyt", "erchayna"; "tu", "fit", "er" and "of" are
    -- heard_as's)
    ayt = "eight", eyt = "eight", nayn = "nine", fayv = "five", van = "one", ziro = "zero",
    fiftin = "fifteen", fifti = "fifty", fortiseben = "forty seven", wer = "where",
    remuv = "remove", lukahed = "lookahead", intarneshnal = "international", swich = "switch", hafhayt = "half height",
    protekshn = "protection", vind = "wind", kansel = "cancel", dilit = "delete", agen = "again", inkris = "increase",
    redi = "ready", orijin = "origin", yu = "you",
    tventi = "twenty", tirti = "thirty", ayti = "eighty", nayndi = "ninety", fortifayv = "forty five",
    flaytlebel = "flight level", flayt = "flight",
    klimb = "climb", reduse = "reduce", poyn = "point", rayt = "right", sey = "say", tern = "turn",
    simulayshn = "simulation", direkt = "direct", reyt = "rate", pasing = "passing", wen = "when",
    turnrayt = "turn right", turnleft = "turn left", mak = "mach", kreyt = "create", kontakt = "contact",
    degri = "degree", degris = "degrees", til = "till", rout = "route", delet = "delete",
    mayl = "mile", mayls = "miles", kanflikt = "conflict", dekimal = "decimal", taym = "time", sho = "show",
    resolushn = "resolution", proseed = "proceed", muv = "move", minits = "minutes", minit = "minute", kros = "cross",
    kontrol = "control", faynal = "final", fastforvard = "fast forward", ercraft = "aircraft",
    destineyshn = "destination", antil = "until", zon = "zone", yor = "your", trayl = "trail",
    trayls = "trails", sori = "sorry", skwok = "squawk", sekond = "second", sekonds = "seconds", rendom = "random",
    ranvey = "runway", pauz = "pause", maintayn = "maintain", duing = "doing", detekshn = "detection",
    apruch = "approach", yuniform = "uniform", vertikal = "vertical", istern = "eastern", sauzern = "southern",
    chayna = "china", erchayna = "air china", koriyan = "korean", emirayts = "emirates", katari = "qatari",
    astanalayn = "astanaline", mongolair = "mongol air" },
  heard_as = {
    { heard = { "write", "rite", "wright" }, means = "right",
      before = { "heading", "hdg", "turn" }, after = { "turn" } },
    -- ("delete de air france", "pausa de simulation": an Italian recogniser's "the" after a word squawk knows;
    -- "ten time", "simulation speed two time": its "times" closing a multiple)
    { heard = { "de", "da" }, means = "the", after = { "#known" } },
    { heard = { "time" }, means = "times", closed_after = { "#number" } },
    -- ("two hundred an fifty knot": a Caribbean recogniser's "and" inside a number)
    { heard = { "an" }, means = "and", between = { { "hundred", "thousand" }, { "#number" } } },
    -- ("conflict resolution em vi pi", "until four dee em ee": letters a recogniser wrote by their names)
    { heard = { "em vi pi", "em vee pee", "em vi pee" }, means = "mvp", after = { "#known" } },
    { heard = { "dee em ee" }, means = "dme", after = { "#number" } },
    -- ("dessend tu seben tousand", "spid tu fifty", "mongol er", "er chayna", "seben tousand fit", "trayl of": a
    -- Mongolian or Kazakh speaker's "to" and "two" alike, "air", "feet" and "off")
    { heard = { "tu" }, means = "to", after = { "descend", "climb" } },
    { heard = { "tu" }, means = "two", before = { "#number" } },
    { heard = { "tu" }, means = "two", after = { "#number" } },
    { heard = { "er" }, means = "air", after = { "mongol", "sverdlovsk" } },
    { heard = { "er" }, means = "air", before = { "china", "chayna" } },
    { heard = { "fit" }, means = "feet", after = { "thousand", "hundred" } },
    { heard = { "of" }, means = "off", closed_after = { "trail", "trails", "nav", "lnav", "vnav", "asas", "reso" } },
    -- ("clai fli level one tree zero": a closing consonant unsaid, only before the level's noun; a cut-off "fli" stays)
    { heard = { "fli" }, means = "flight", before = { "level", "levels" } },
    -- ("level off where you are": the level flown now, no question where the aircraft is)
    { heard = { "where you are", "where he is", "where she is", "where it is" }, means = "at present level",
      after = { "off" } },
    -- ("pausa la simulazione": an Italian "the")
    { heard = { "la" }, means = "the", before = { "simulazione", "simulation", "sim" } },
    -- ("mvp + vs reso": the resolutions' vertical speed)
    { heard = { "vs" }, means = "vertical", before = { "reso", "resolution", "resolutions" } },
    -- ("lookahead time two minute fa conflic detection": its "for")
    { heard = { "fa" }, means = "for", before = { "conflict", "conflic", "the", "detection" } },
    -- ("turn lefchi hiding zero six zero", "say hiding": a Brazilian recogniser's "heading")
    { heard = { "hiding" }, means = "heading", before = { "#number" },
      after = { "left", "right", "present", "your", "say", "fly", "the", "his", "its" } },
    -- ("switch of lnav": a recogniser's "off" after "switch")
    { heard = { "of" }, means = "off", after = { "switch", "switched" } },
    -- ("descen fly leven one zero zero": a Thai or Vietnamese recogniser's flight level)
    { heard = { "fly" }, means = "flight", before = { "leven" } },
    -- ("climb on fligt level one four tsero tank you": a German recogniser's thanks)
    { heard = { "tank", "tenk", "sank" }, means = "thank", before = { "you" } },
    -- ("throw in 3 more A320s", "throw in another B738": adding traffic)
    { heard = { "throw in", "chuck in" }, means = "add", before = { "#number", "a", "an", "another", "some", "more" } },
    -- ("turn lift heading three four zero": a recogniser's "left")
    { heard = { "lift", "loft", "laughed" }, means = "left", after = { "turn" } },
    { heard = { "the send", "this end", "the scent", "the scend", "decent", "dissent", "diss end" }, means = "descend",
      before = { "#number", "flight", "level", "altitude", "to", "fly", "and", "at" } },
    -- (a Japanese or Korean accent: "turn ride", "turn light" (four writers of five); "plight level", "fright revel",
    -- "flight rebel", "flight label"; "crime and maintained"; "maintenance flight level"; "descend pour thousand";
    -- "one two sick one"; "set rook ahead time")
    { heard = { "ride", "light" }, means = "right", after = { "turn" } },
    { heard = { "plight", "fright" }, means = "flight", before = { "level", "rebel", "label", "revel" } },
    { heard = { "rebel", "label", "revel" }, means = "level", after = { "flight", "plight", "fright" } },
    { heard = { "rook" }, means = "look", before = { "ahead" } },
    { heard = { "crime" }, means = "climb", before = { "#number", "and", "flight", "plight", "to", "level" } },
    -- (an Arabic accent: "qatari eight alpha bravo claim flight level two three zero")
    { heard = { "claim" }, means = "climb", before = { "#number", "flight", "level", "to", "and" } },
    -- ("vertical speed one thousand feet claim": the verb closing a rate)
    { heard = { "claim" }, means = "climb", closed_after = { "feet", "ft", "fpm", "minute" } },
    { heard = { "maintenance" }, means = "maintain", before = { "#number", "flight", "plight", "level", "altitude" } },
    { heard = { "pour" }, means = "four", before = { "thousand", "hundred" } },
    -- (a Korean accent's "pour" inside a number or before a unit: "flight level one pour zero", "pour times",
    -- "until pour dme")
    { heard = { "pour" }, means = "four", before = { "#number", "times", "dme", "mile", "miles", "nm", "degrees",
      "knots", "knot" } },
    { heard = { "pour" }, means = "four", after = { "#number" } },
    { heard = { "sick" }, means = "six", before = { "thousand", "hundred" } },
    -- (a Thai or Vietnamese accent: "ay" for eight and "tu" for two among digits, "not" for knots closing a speed,
    -- "tie" for Thai before a flight number, "men tain", "flight lever", "a sas")
    { heard = { "ay" }, means = "eight", between = { { "#number" }, { "#number", "thousand", "hundred", "knots" } } },
    { heard = { "ay" }, means = "eight", after = { "#number" } },
    { heard = { "ay" }, means = "eight", before = { "thousand", "hundred" } },
    { heard = { "ay" }, means = "eight", between = { { "pass", "passing", "level", "heading", "speed", "to", "at", "fl",
      "mach", "point", "decimal", "reduce", "increase", "climb", "descend" }, { "#number", "thousand", "hundred" } } },
    { heard = { "tu" }, means = "two", between = { { "#number" }, { "#number" } } },
    { heard = { "not" }, means = "knots", closed_after = { "#number" } },
    { heard = { "tie" }, means = "thai", before = { "#number" } },
    -- (a Polish, Czech or Slovak accent: "hitting" for heading, "spit" for speed, "nuts" for knots, "loft hansa")
    { heard = { "hitting" }, means = "heading", before = { "#number" },
      after = { "present", "say", "your", "right", "left", "turn", "the", "current", "is", "fly" } },
    { heard = { "hitting" }, means = "heading", closed_after = { "present", "say", "your", "current" } },
    { heard = { "spit" }, means = "speed", before = { "#number" },
      after = { "reduce", "increase", "maintain", "say", "your", "the", "present", "current", "is" } },
    { heard = { "spit" }, means = "speed", closed_after = { "say", "your", "present", "current" } },
    { heard = { "nuts" }, means = "knots", after = { "#number" } },
    { heard = { "loft hansa", "luft hansa" }, means = "lufthansa", before = { "#number" } },
    -- (a Dutch or Flemish accent: "proceed the rect SPY", "de rect")
    { heard = { "the rect", "de rect" }, means = "direct", after = { "proceed", "fly", "route", "go", "then", "and" } },
    { heard = { "men tain" }, means = "maintain", before = { "#number", "flight", "fly", "level", "altitude", "heading",
      "speed", "present", "mach" } },
    { heard = { "lever", "liver" }, means = "level", after = { "flight", "fly" } },
    -- ("switch off l nav", "v nav on": the switch's letters said apart)
    { heard = { "l nav" }, means = "lnav", before = { "on", "off", "#known" }, after = { "off", "on", "the", "your", "of" } },
    { heard = { "v nav" }, means = "vnav", before = { "on", "off", "#known" }, after = { "off", "on", "the", "your", "of" } },
    { heard = { "a sas" }, means = "asas", after = { "on", "off" }, before = { "on", "off" } },
    { heard = { "sick" }, means = "six", between = { { "#number" }, { "#number", "knots", "thousand", "hundred" } } },
    { heard = { "sick" }, means = "six", between = { { "#known" }, { "#number" } } },
    -- ("descent fly-level wan zero zero": the noun heard for the verb before a flight level)
    { heard = { "descent" }, means = "descend", before = { "flight", "fly-level" } },
    -- ("when passing fly level one zero zero turn right": "flight level" as a recogniser writes it, before its
    -- number)
    { heard = { "fly level" }, means = "flight level", before = { "#number" } },
    { heard = { "head in", "heading's" }, means = "heading", before = { "#number" } },
    -- ("show me the root": the route as a recogniser writes it, after its determiner)
    { heard = { "root" }, means = "route", after = { "the", "your", "its", "his", "her", "their" } },
    -- ("run the simulation at for times real time": a multiplier's digit heard as a word; "speed it up times for",
    -- "turn left by for zero degrees", "fifty for decimal fife north", "speedbird won for tree for reduce ...": a
    -- digit after "times" closing it, or after "by", before a decimal's point, or after a digit said as a word before
    -- the instruction's verb: "1000 for descend" is no four)
    { heard = { "for", "fore" }, means = "four", before = { "times" } },
    { heard = { "for" }, means = "four", closed_after = { "times" } },
    { heard = { "for" }, means = "four", between = { { "by" }, { "#number" } } },
    { heard = { "for" }, means = "four", between = { { "#number" }, { "decimal", "point" } } },
    { heard = { "for" }, means = "four", between = { { "zero", "one", "two", "three", "four", "five", "six", "seven",
      "eight", "nine", "niner", "tree", "fife", "won" }, { "climb", "descend", "reduce", "increase", "turn", "maintain",
      "proceed", "direct", "fly", "speed", "heading" } } },
    -- ("descend and maintain ate thousand", "mach point ate one", "one ate zero": a recogniser's "eight" beside a
    -- number or before its count)
    { heard = { "ate" }, means = "eight", before = { "#number", "thousand", "hundred" } },
    { heard = { "ate" }, means = "eight", after = { "zero", "one", "two", "three", "four", "five", "six", "seven", "eight",
      "nine", "niner", "tree", "fife", "won", "point", "decimal" } },
    -- ("set the time multiplier to too": a digit closing the request after "to" or "times")
    { heard = { "too" }, means = "two", closed_after = { "to", "times" } },
    { heard = { "nots", "notts", "nuts", "knot's" }, means = "knots", after = { "#number" } },
    -- ("add also AKADO at the end": an Italian speaker's "aggiungi anche", the adverb after the verb)
    { heard = { "add also" }, means = "also add", before = { "#code" } },
    -- (a rate's unit with its noun in the plural, "1500 feet per minutes", "2000 ft per mins")
    { heard = { "minutes", "mins" }, means = "minute", after = { "per" } },
    -- the radiotelephony digits as speech recognition writes them: "niner" split in two ("flight level nigh ner
    -- zero"), "tree" heard as "free" before the count it multiplies or between digits ("descend to free thousand",
    -- "heading one free zero"); "free" elsewhere is English ("feel free to climb")
    { heard = { "nigh ner", "nye ner", "ni ner" }, means = "niner", before = { "#number", "thousand", "hundred" },
      after = { "#number", "level", "fl", "heading", "hdg" } },
    { heard = { "free" }, means = "three", before = { "thousand", "hundred" } },
    { heard = { "free" }, means = "three", between = { { "#number" }, { "#number" } } },
    -- (Mandarin, "l" for "r" and "r" for "l": "descend lay one thousand five hundred feet per minute", "fry heading
    -- zero one zero", "fry direct DALUE")
    { heard = { "lay" }, means = "rate", before = { "#number" } },
    -- (Indonesian: "pas porward tree minute", fast forward with /f/ said /p/)
    { heard = { "pas" }, means = "fast", before = { "porward", "forward" } },
    { heard = { "fry" }, means = "fly", before = { "heading", "hdg", "direct", "dct", "present" } },
    -- ("descend thre thousand feet", "heading one thre zero": "three" typed with a letter left out, beside a number)
    { heard = { "thre" }, means = "three", before = { "#number" }, after = { "#number" } },
    -- German "rechts"/"links" (right/left; lexicon.said_whole.dutch reads them in a Dutch sentence): straight before
    -- a number, no "kurs" (heading) between, the side of a turn that number may be the degrees of ("rechts 20",
    -- "links 090", "rechts 200": read as "turn right ..." is, asked where the heading and the turn differ); after
    -- a number or before a heading's word, the side alone ("30 links", "20 grad rechts", "links kurs 090")
    { heard = { "rechts" }, means = "turn right", before = { "#number" }, not_after = { "turn", "heading", "hdg" } },
    { heard = { "links" }, means = "turn left", before = { "#number" }, not_after = { "turn", "heading", "hdg" } },
    { heard = { "rechts" }, means = "right", before = { "heading", "hdg", "to", "on", "onto", "auf", "kurs", "steuerkurs",
        "turn" }, after = { "#number", "degrees", "degree", "grad", "turn" } },
    { heard = { "links" }, means = "left", before = { "heading", "hdg", "to", "on", "onto", "auf", "kurs", "steuerkurs",
        "turn" }, after = { "#number", "degrees", "degree", "grad", "turn" } },
    -- German "an"/"ein" (on) and "aus" (off) straight after what is switched ("vnav ein", "trails an", "asas aus",
    -- "lnav aus kurs 240"); elsewhere "an" is English's article and "ein" Aer Lingus's code
    { heard = { "an", "ein" }, means = "on", after = { "vnav", "lnav", "trail", "trails", "asas", "cdr", "reso",
                                                     "resolution", "detection", "swrad" } },
    { heard = { "aus" }, means = "off", after = { "vnav", "lnav", "trail", "trails", "asas", "cdr", "reso",
                                                "resolution", "detection", "swrad" } },
    { heard = { "two", "too" }, means = "to",
      between = { { "climb", "descend", "maintain", "turn", "left", "right", "reduce", "increase" },
                  { "flight", "level", "fl", "heading", "speed", "altitude" } } },
    -- French phraseology before its value said in English, read the same way ("cap 270", "monte FL150", a
    -- place name's word elsewhere; French said whole is lexicon.said_whole.french)
    { heard = { "cap" }, means = "heading", before = { "#number" }, not_after = { "red" } },
    { heard = { "niveau" }, means = "flight level", before = { "#number" } },
    -- the Russian-speaking controller's word for a flight level ("эшелон": "climb and maintain echelon 180")
    { heard = { "echelon", "eshelon" }, means = "flight level", before = { "#number" } },
    -- (and the metres a level is given in, as Russian says them after the number: "descend 3000 metrov", "2400
    -- metrov", "1200 metra")
    { heard = { "metrov", "metra", "metr" }, means = "metres", after = { "#number" } },
    { heard = { "vitesse" }, means = "speed", before = { "#number", "mach" } },
    { heard = { "monte" }, means = "climb", before = { "#number", "niveau", "a", "fl" } },
    -- Spanish words said in an English clearance that are also Portuguese or Italian, read only where
    -- the instruction word is expected (lexicon.said_whole.spanish.joining: "suba flight level 260", "descend y
    -- maintain", "climb 5 mil feet")
    { heard = { "suba" }, means = "climb", before = { "#number", "a", "y", "fl", "flight", "level", "to" } },
    { heard = { "y" }, means = "and", between = { { "suba", "descend", "climb" }, { "maintain" } } },
    { heard = { "mil" }, means = "thousand", after = { "#number" } },
    -- Dutch "een" (a, one) beside a number is the digit ("vliegniveau een twee nul"); "maak een" is
    -- lexicon.said_whole.dutch's, elsewhere it stays unaccounted for, and is asked
    { heard = { "een" }, means = "one", before = { "#number" }, after = { "#number" } },
    -- (English typed by a Spanish speaker: "procede direct GAVOL", as "proceder" is spelled)
    { heard = { "procede", "proced" }, means = "proceed", before = { "direct", "direct-to", "to" } },
    -- (a condition in a Spanish or Portuguese speaker's English, after "when" or "once": the verb not agreeing
    -- with its subject, "arrive to" for "llegar a" / "chegar a", "be with" a speed for "estar con": "when it pass
    -- over TOBEK", "when you arrive to RINOR", "when arrives to FL250", "when you are at CASAR", "when you are
    -- with 250 knots"; read as the condition English says; a longer form before the shorter it opens with)
    -- ("then as soon as it is level turn right heading 060", "Mach .78 as soon as level": "once"; "as soon as
    -- possible" and "as soon as you can" stay the courtesy they are; "as soon as Swiss 200 is level", a name typed
    -- with its capital after it, is the condition on that aircraft, never a courtesy that drops its callsign)
    -- ("Whenever the Qeshm Air 1224 passes RABAM, it should climb ...", "... whenever its speed became 190, descend":
    -- a Persian speaker's "har vaght", the one-time condition "when" is; "whenever convenient" stays the courtesy)
    { heard = { "whenever" }, means = "when",
      before = { "#capital", "the", "it", "it's", "its", "he", "he's", "his", "she", "she's", "her", "they", "they're",
                 "passing", "reaching", "level", "established", "past" } },
    -- ("when it passed FL130 its speed should become 280", "after it passed flight level 150": the past a Persian
    -- speaker gives the condition's verb, read as passing the level said after it)
    -- ("it should go to heading 240": "go to" a heading, as a Persian speaker's "beravad" is said, is flying it)
    { heard = { "go to heading", "go on heading", "goes to heading" }, means = "fly heading", before = { "#number" } },
    -- (and before a fix typed in capitals, as a Hungarian, Romanian or Ukrainian speaker says it: "heading 070
    -- when it passed ABATU" is passing ABATU)
    { heard = { "it passed", "he passed", "she passed", "you passed" }, means = "passing",
      between = { { "when", "whenever", "once", "after" }, { "#number", "fl", "flight", "level", "altitude", "#code" } } },
    { heard = { "it reached", "he reached", "she reached", "you reached" }, means = "reaching",
      between = { { "when", "whenever", "once", "after" }, { "#number", "fl", "flight", "level", "altitude" } } },
    -- ("descend FL310, when reach, Mach .79", "when reach FL100 turn left": the verb's bare form, as a Japanese or
    -- Chinese speaker says it, is reaching)
    -- ("when you get two hundred descend ...": "get" between the aircraft and a value is "reach")
    { heard = { "get", "gets" }, means = "reach", between = { { "you", "it", "he", "she", "they" }, { "#number" } } },
    { heard = { "reach" }, means = "reaching", closed_after = { "when", "once", "upon", "on" },
      between = { { "when", "once", "upon", "on" }, { "#number", "fl", "flight", "level", "altitude" } } },
    { heard = { "as soon as" }, means = "once",
      before = { "#capital", "the", "it", "it's", "he", "he's", "she", "she's", "they", "they're", "you're", "level", "lvl", "reaching",
                 "passing", "past", "established" } },
    { heard = { "you pass over", "it pass over", "it passes over", "pass over", "passes over", "you pass",
                "it pass" }, means = "passing", after = { "when", "once" } },
    { heard = { "you arrive to", "you arrive at", "it arrive to", "it arrive at", "arrive to", "arrive at" },
      means = "you reach", after = { "when", "once", "after" } },
    { heard = { "it arrives to", "it arrives at", "arrives to", "arrives at" }, means = "it reaches",
      after = { "when", "once", "after" } },
    { heard = { "you are at" }, means = "it is at", after = { "when", "once" } },
    -- (and typed fast with the apostrophe left out: "when shes at mach .8", "once hes at FL230")
    { heard = { "shes at", "hes at", "its at", "theyre at", "youre at" }, means = "it is at",
      after = { "when", "once" } },
    -- (the aircraft as "he" or "she", the verb not agreeing, as a French or Arabic speaker says it: "when he arrive
    -- at LAKAM, he must descend ...", "descend FL320 when she arrive at GALIT")
    { heard = { "he arrive to", "he arrive at", "she arrive to", "she arrive at", "he arrives to", "he arrives at",
                "she arrives to", "she arrives at" }, means = "it reaches", after = { "when", "once", "after" } },
    -- (and the future said for the present, as an Italian or Russian speaker says it: "when he will arrive at TIBER,
    -- descend ...", "once it will arrive to LUGAN")
    { heard = { "he will arrive at", "he will arrive to", "she will arrive at", "she will arrive to",
                "it will arrive at", "it will arrive to", "you will arrive at", "you will arrive to" },
      means = "it reaches", after = { "when", "once", "after" } },
    -- (and after "after", a Greek speaker's "after he arrives to XORKI, descend ...": the place reached)
    -- (a Portuguese speaker's "chegar em", arriving "in" a place: "when he arrives in BOTOM he must descend ...",
    -- "when it arrives in FL250")
    { heard = { "you arrive in", "it arrive in", "arrive in" }, means = "you reach", after = { "when", "once" } },
    { heard = { "it arrives in", "arrives in", "he arrive in", "she arrive in", "he arrives in", "she arrives in" },
      means = "it reaches", after = { "when", "once" } },
    -- (a rate said "feet minute", as French "pieds minute": "descend FL100 at 1800 feet minute")
    { heard = { "feet minute", "ft minute" }, means = "feet per minute", after = { "#number" } },
    -- (and "arrive" said alone, for "llegar" / "chegar" with no place: "descend FL180 and when you arrive reduce
    -- to 250", "when it arrives there": the level or place this request cleared it to, G:reached_opening)
    { heard = { "you arrive there", "it arrives there", "it arrive there", "you arrive", "it arrives", "it arrive" },
      means = "you get there", after = { "when", "once" } },
    -- ("when you are over VIPSA descend FL120": "estar sobre", the waypoint passed)
    { heard = { "you are over", "it is over", "you're over", "it's over" }, means = "passing",
      after = { "when", "once" } },
    -- (the aircraft's speed as its own, "his" or "her" as Portuguese "a velocidade dele" says it: "when his speed is
    -- 250 knots", "once its speed is 260 kt": the speed reached, as "when it is at 250 knots")
    { heard = { "his speed is", "her speed is", "its speed is" }, means = "it is at",
      between = { { "when", "once" }, { "#number" } } },
    { heard = { "you are with", "it is with", "you're with", "it's with" }, means = "it is at",
      between = { { "when", "once" }, { "#number", "fl", "flight", "speed", "mach" } } },
    -- (the aircraft called "he" or "she", as a speaker of a language whose noun for it has that gender says it,
    -- Polish "on", Russian "он", German "er": "when he is over EROBI descend FL70", "once she's at FL100")
    { heard = { "he is over", "she is over", "he's over", "she's over" }, means = "passing", after = { "when", "once" } },
    { heard = { "he is at", "she is at", "he's at", "she's at" }, means = "it is at", after = { "when", "once" } },
    -- (false friends of a Spanish or Portuguese speaker for the simulation's clock: "put the simulation in normal
    -- velocity again" for "velocidad" / "velocidade", "fast the simulation 30 minutes" for fast-forward)
    { heard = { "velocity" }, means = "speed", after = { "normal", "double" } },
    { heard = { "fast" }, means = "fast forward", before = { "the", "sim", "simulation" } },
    -- (the detection's look-ahead said as a Spanish or Portuguese speaker says it: "put the conflict detection
    -- looking 8 minutes in front", "mirando 8 minutos adelante")
    { heard = { "looking" }, means = "look-ahead", between = { { "detection", "probe", "asas" }, { "#number" } } },
    { heard = { "in front" }, means = "ahead", after = { "minutes", "minute", "mins", "min", "seconds", "secs" } },
    -- (a Chinese controller's words for the detection, "冲突探测" said word for word: "turn on the conflict detect",
    -- and "打开"/"关闭" as "open"/"close" straight after the module switched: "conflict detect close", "conflict
    -- detection open")
    { heard = { "detect" }, means = "detection", after = { "conflict", "conflicts" } },
    { heard = { "close", "closed" }, means = "off", after = { "detection", "detect", "asas", "cdr", "reso" } },
    { heard = { "open", "opened" }, means = "on", after = { "detection", "detect", "asas", "cdr", "reso" } },
  },
  -- The discourse words of the languages aviation staff speak, dropped into an English request ("KLM12 descend FL200,
  -- iie, FL210", "climb FL300 phir turn left heading 270", "hapana, heading 250", "speed 250 dhanyavaad"): language
  -- -> role -> words (lower case, with and without accents). A word is read as its role's English
  -- (discourse_roles) in every sentence, as lexicon.said_whole's shared words are (grammar.lua G.said_whole_index).
  -- A word of two letters or less is never listed ("ne" is yes in Korean and Greek and no in Czech and Serbian;
  -- "da", "nu", "ja", "to" are English, idents or units), nor one that is an English word, a fix or navaid ident
  -- ("hai", "sonra", "tapos", "bukan" are fixes) or a callsign's word; a word listed under two roles (in any two languages) or read otherwise by
  -- lexicon.said_whole, foreign_digits, accounted or fillers is left to them; so are the `wait` role's
  -- words ("matte, climb FL300": a hold before an instruction is no instruction). The `moment` role's words are
  -- English "one moment", read as it is: beside a pause ("Pause, chotto matte.") or before a value taken back
  -- ("climb FL380, chotto matte... negative, FL370"), and asked before an instruction ("chotto matte, climb
  -- FL300").
  discourse_roles = { yes = "yes", no = "no", sorry = "sorry", ["then"] = "then", ["and"] = "and", okay = "okay",
    please = "please", thanks = "thanks", wait = false, moment = "one moment" },
  discourse_words = {
    japanese = { no = { "iie" }, sorry = { "gomen", "gomennasai", "shitsurei", "sumimasen" },
      ["then"] = { "sorekara" }, ["and"] = { "soshite" }, wait = { "matte", "ano ne" }, moment = { "chotto matte" },
      please = { "onegaishimasu", "onegai" }, thanks = { "arigato", "arigatou" } },
    chinese = { yes = { "shide", "dui de" }, no = { "budui", "bu shi", "bu dui" },
      sorry = { "duibuqi", "dui bu qi", "buhaoyisi" }, ["then"] = { "ranhou" }, wait = { "dengyixia", "shaodeng" },
      okay = { "haode", "hao de" }, please = { "qing" }, thanks = { "xiexie", "xie xie" } },
    korean = { no = { "aniyo", "anio", "aniya" }, sorry = { "joesonghamnida", "mianhamnida", "mianhae" },
      ["then"] = { "geurigo naseo", "daeume" }, ["and"] = { "geurigo" }, wait = { "jamkkanman", "jamkanman" },
      please = { "juseyo" }, thanks = { "kamsahamnida", "gamsahamnida" } },
    hindi_urdu = { yes = { "haan", "ji haan", "haanji" }, no = { "nahin", "nahi", "nahee" },
      sorry = { "maafi", "maaf kijiye", "kshama" }, ["then"] = { "phir", "uske baad" },
      wait = { "ruko", "rukiye" }, okay = { "theek hai", "thik hai", "achha", "accha" },
      please = { "kripya", "meherbani" }, thanks = { "shukriya", "dhanyavad", "dhanyavaad", "dhanyawad" } },
    portuguese = { yes = { "positivo", "afirmativo" }, sorry = { "desculpe", "perdão", "perdao" },
      okay = { "ciente", "beleza" } },
    arabic = { yes = { "naam", "aywa", "aiwa" }, sorry = { "aasif", "mutaassif" },
      ["then"] = { "thumma", "baadain", "badain" }, wait = { "lahza", "lahtha", "istanna" },
      okay = { "tayyib", "tayeb", "mashi" }, please = { "min fadlak", "min fadlik", "law samaht" },
      thanks = { "shukran" } },
    turkish = { yes = { "evet" }, no = { "hayir", "hayır" }, sorry = { "affedersiniz", "kusura bakmayin" },
      ["then"] = { "ondan sonra" }, wait = { "bekle", "bekleyin", "bir dakika" }, okay = { "tamam", "peki" },
      please = { "lutfen", "lütfen" }, thanks = { "tesekkurler", "teşekkürler", "sagol", "sağol" } },
    farsi = { yes = { "baleh" }, no = { "nakheir", "nakhair" }, sorry = { "bebakhshid", "bebakhshin", "mazerat" },
      ["then"] = { "baadesh", "bad az an" }, wait = { "sabr kon", "sabr konid", "ye lahze" }, okay = { "bashe", "baashe" },
      please = { "lotfan" }, thanks = { "mamnoon", "mamnun", "motashakkeram" } },
    thai = { sorry = { "khothot", "kho thot", "khor tod", "kor tot" }, wait = { "sakkhru", "sak khru", "diao" },
      thanks = { "khop khun", "khob khun", "khopkhun" } },
    vietnamese = { yes = { "vang", "vâng" }, no = { "khong", "không" }, sorry = { "xin loi", "xin lỗi" },
      ["then"] = { "sau do", "sau đó" }, wait = { "doi chut", "đợi chút", "cho chut", "chờ chút" },
      okay = { "duoc roi", "được rồi" }, thanks = { "cam on", "cảm ơn" } },
    indonesian = { no = { "tidak" }, sorry = { "maaf" }, ["then"] = { "lalu", "kemudian" },
      wait = { "tunggu", "sebentar" }, please = { "tolong", "silakan" }, thanks = { "terima kasih" } },
    tagalog = { sorry = { "pasensya", "pasensiya", "paumanhin" }, ["then"] = { "pagkatapos" },
      wait = { "sandali", "teka" }, okay = { "sige" }, please = { "pakiusap" }, thanks = { "salamat" } },
    swahili = { yes = { "ndiyo", "ndio" }, no = { "hapana" }, sorry = { "samahani" },
      ["then"] = { "kisha", "halafu", "baadaye" }, wait = { "subiri", "ngoja" }, okay = { "sawa" },
      please = { "tafadhali" }, thanks = { "asante" } },
    hausa = { sorry = { "yi hakuri", "gafara" }, ["then"] = { "sannan" }, wait = { "dakata" }, okay = { "shikenan" },
      please = { "don allah" }, thanks = { "nagode", "na gode" } },
    yoruba = { yes = { "beeni", "bẹẹni" }, sorry = { "ema binu", "e ma binu" },
      ["then"] = { "lehinna", "lẹhinna" }, please = { "ejowo", "jowo" }, thanks = { "e se", "o se" } },
    igbo = { please = { "biko" }, thanks = { "daalu", "dalu" } },
    afrikaans = { sorry = { "jammer", "verskoon" }, ["then"] = { "daarna" }, wait = { "oomblik" },
      please = { "asseblief" }, thanks = { "dankie" } },
    zulu = { yes = { "yebo" }, sorry = { "uxolo", "ngiyaxolisa" }, ["then"] = { "bese", "ngemuva" },
      ["and"] = { "futhi" }, okay = { "kulungile" }, please = { "ngicela" },
      thanks = { "ngiyabonga" } },
    hebrew = { sorry = { "slicha", "sliha", "selicha" }, ["then"] = { "achar kach", "ahar kah" }, wait = { "rega" },
      okay = { "beseder", "be seder" }, please = { "bevakasha" }, thanks = { "todah", "toda raba" } },
    hungarian = { yes = { "igen" }, sorry = { "bocsanat", "bocsánat", "elnezest", "elnézést" },
      ["then"] = { "aztan", "aztán" }, wait = { "varj", "várj", "varjon", "egy pillanat" }, okay = { "rendben" },
      please = { "kerem", "kérem" }, thanks = { "koszonom szepen", "köszönöm szépen", "koszonom", "köszönöm", "koszi" } },
    czech_slovak = { sorry = { "promin", "prominte", "promiňte", "prepacte", "prepáčte" },
      ["then"] = { "potom" }, wait = { "pockej", "pockejte", "počkejte", "pockajte", "počkajte" },
      okay = { "jasne", "jasně" }, please = { "prosim", "prosím" },
      thanks = { "dekuji", "děkuji", "dakujem", "ďakujem", "diky", "díky" } },
    romanian = { sorry = { "scuze", "scuzati", "scuzați" }, ["then"] = { "apoi" },
      wait = { "asteapta", "așteaptă", "asteptati", "o clipa" }, please = { "va rog", "vă rog" },
      thanks = { "multumesc", "mulțumesc" } },
    serbian_croatian = { sorry = { "izvini", "izvinite", "oprosti", "oprostite" }, ["then"] = { "onda", "zatim" },
      wait = { "cekaj", "čekaj", "cekajte", "sacekaj", "samo malo" }, okay = { "dobro", "vazi", "važi" },
      please = { "molim" }, thanks = { "hvala" } },
    bulgarian = { sorry = { "izvinete", "izvinyavai", "sazhalyavam" }, ["then"] = { "sled tova" },
      wait = { "pochakai", "pochakaite" }, please = { "molya" }, thanks = { "blagodarya" } },
    ukrainian = { sorry = { "vybachte", "probachte" }, ["then"] = { "potim" }, wait = { "zachekaite", "zachekayte" },
      please = { "bud laska" }, thanks = { "dyakuyu", "diakuiu" } },
    finnish = { yes = { "kyllä" }, sorry = { "anteeksi" }, ["then"] = { "sitten" },
      wait = { "odota", "hetkinen" }, okay = { "selvä" }, thanks = { "kiitos" } },
    estonian = { yes = { "jah" }, sorry = { "vabandust", "vabandage" }, ["then"] = { "seejarel", "seejärel" },
      wait = { "oota", "oodake" }, okay = { "olgu" }, please = { "palun" }, thanks = { "aitah", "tanan", "tänan" } },
    amharic = { yes = { "awo" }, no = { "aydelem" }, sorry = { "yikirta", "yiqirta" }, ["then"] = { "kezya" },
      please = { "ebakih", "ebakish" }, thanks = { "ameseginalehu", "amesegnalehu" } },
    lithuanian = { yes = { "taip" }, sorry = { "atsiprasau", "atsiprašau" }, ["then"] = { "paskui" },
      wait = { "palaukite", "palauk" }, okay = { "gerai" }, please = { "prasau", "prašau" }, thanks = { "aciu", "ačiū" } },
    latvian = { sorry = { "atvainojiet", "piedodiet" }, wait = { "pagaidiet", "uzgaidiet" },
      please = { "ludzu", "lūdzu" }, thanks = { "paldies" } },
    dutch = { yes = { "klopt" }, thanks = { "dank je wel", "dank u wel" } },
    french = { okay = { "d'accord", "daccord" }, thanks = { "merci beaucoup" } },
    german = { sorry = { "entschuldigung", "verzeihung", "entschuldigen sie" } },
    swiss_german = { sorry = { "exgüsi", "exgusi", "exgüsee" }, thanks = { "merci vielmal", "merci vilmal" } },
    greek = { sorry = { "signomi", "signómi", "syngnomi", "syggnomi" } },
  },
  -- A language said whole by a controller or instructor ("vire a la izquierda rumbo 170", "borra el iberia
  -- 6253", "montez au niveau 140", "tournez à gauche cap 030"), read as its English word for word (grammar.lua
  -- G.said_whole): one table per language, word or phrase (lower case, with and without its accents) ->
  -- English. A sentence holding a word or phrase of a language's `words` not in its `shared` is in that
  -- language: there every word or phrase of its `words` and `joining` and every digit of foreign_digits is
  -- read as its English; elsewhere only those of `words`. A word of the language in none of them stays
  -- unaccounted for, and is asked.
  said_whole = {
  spanish = {
    words = {
      -- instructions and their nouns
      vire = "turn", gire = "turn", izquierda = "left", derecha = "right", ["a la izquierda"] = "left",
      ["a la derecha"] = "right", ["por la izquierda"] = "left", ["por la derecha"] = "right",
      grados = "degrees", rumbo = "heading", nivel = "level", ["nivel de vuelo"] = "flight level", vuelo = "flight",
      velocidad = "speed", ["velocidad doble"] = "double speed", baje = "descend", descienda = "descend",
      ascienda = "climb", mantenga = "maintain", mantener = "maintain",
      -- (what is flown now, kept: read with its verb only; false: said alone, the phrase stays as said, and
      -- is asked)
      ["rumbo actual"] = false, ["velocidad actual"] = false, ["nivel actual"] = false,
      ["mantenga rumbo actual"] = "maintain present heading", ["mantener rumbo actual"] = "maintain present heading",
      ["mantenga velocidad actual"] = "maintain present speed", ["mantener velocidad actual"] = "maintain present speed",
      ["mantenga nivel actual"] = "maintain present level", ["mantener nivel actual"] = "maintain present level",
      reduzca = "reduce", aumente = "increase", proceda = "proceed", vuele = "fly", directo = "direct",
      ["directo a"] = "direct to", ["directo al"] = "direct to", cruce = "cross", cruzar = "cross",
      -- (the gerund opening a condition: "cruzando DORSA descend level 160", when crossing it)
      cruzando = "when crossing",
      cruza = "cross", indique = "say", ["donde esta"] = "where is", ["dónde está"] = "where is",
      ["donde está"] = "where is", ["cual es"] = "what is", ["cuál es"] = "what is",
      -- (the informal imperative and the infinitive: "baja a nivel 90", "virar derecha")
      baja = "descend", bajar = "descend", descender = "descend", sube = "climb", subir = "climb",
      ascender = "climb", vira = "turn", gira = "turn", virar = "turn", girar = "turn", grado = "degree",
      altitud = "altitude", ["velocidad vertical"] = "vertical speed", descenso = "descent", ascenso = "climb",
      ["despues de"] = "after", ["después de"] = "after", ["antes de"] = "before", ahora = "now",
      metros = "metres", milla = "mile", nauticas = "nautical", ["náuticas"] = "nautical",
      -- the rate of a climb or descent ("descienda con régimen 1000 pies por minuto"; "regimo" as heard)
      ["régimen"] = "rate", regimen = "rate", regimo = "rate", ["por minuto"] = "per minute",
      pies = "feet", nudos = "knots", millas = "miles", minutos = "minutes", minuto = "minute",
      segundos = "seconds",
      -- the experimenter's commands
      borra = "delete", borre = "delete", borrar = "delete", elimina = "delete", elimine = "delete",
      mueve = "move", mueva = "move", mover = "move", crea = "create", cree = "create", crear = "create",
      destino = "destination", origen = "origin", listar = "list", liste = "list", ruta = "route",
      continua = "continue", ["continúa"] = "continue", corre = "run", ["dale play"] = "press play",
      simulacion = "simulation", ["simulación"] = "simulation", adelanta = "advance", adelante = "advance",
      activa = "activate", activar = "activate", desactiva = "deactivate",
      resolucion = "resolution", ["resolución"] = "resolution", ["zona protegida"] = "protected zone",
      ["tiempo de anticipacion"] = "look-ahead time", ["tiempo de anticipación"] = "look-ahead time",
      doble = "double", veces = "times", pausa = "pause", pausar = "pause", pause = "pause",
      inicia = "start", iniciar = "start", inicie = "start", arranca = "start", comienza = "start",
      empieza = "start", ["detén"] = "stop", deten = "stop", detenga = "stop", detener = "stop",
      reinicia = "reset", reiniciar = "reset", reinicie = "reset", escenario = "scenario", carga = "load",
      cargue = "load", cargar = "load", agrega = "add", agregue = "add", ["añade"] = "add", anade = "add",
      ["añada"] = "add", anada = "add", quita = "remove", retira = "remove",
      nuevo = "new", nueva = "new", avion = "aircraft", ["avión"] = "aircraft", aeronave = "aircraft",
      ["deteccion de conflictos"] = "conflict detection", ["detección de conflictos"] = "conflict detection",
      -- a value taken back and said again ("climb to FL190, perdón, FL180"; "corrijo": I correct)
      perdon = "sorry", ["perdón"] = "sorry", perdona = "sorry", ["perdóname"] = "sorry", perdoname = "sorry",
      disculpe = "sorry", disculpa = "sorry", corrijo = "correction", correccion = "correction",
      ["corrección"] = "correction",
      -- (and a speaker's "I mean", "rather", "that is" before it: "FL190, mejor dicho, 200", "o sea", "digo")
      ["mejor dicho"] = "I mean", ["o sea"] = "I mean", digo = "I mean",
      -- (the Spanish spelling of "okay")
      okey = "okay",
      -- a moment asked for ("pause, un momento por favor": as English "one moment")
      ["un momento"] = "one moment",
      -- a Mexican controller's radio words in an English clearance: a value taken back ("left heading 090...
      -- negativo, right heading 090"), one said again to confirm it ("six thousand, correcto, seis mil"), a
      -- speed kept until the final's miles ("velocidad 160 hasta 5 millas final"), a new aircraft's place
      -- ("sobre TPX"), the simulation's clock ("acelera la simulación por 4", "avanza la simulación 3 minutos")
      negativo = "negative", correcto = "correct", hasta = "until", sobre = "over", acelera = "accelerate",
      acelere = "accelerate", acelerar = "accelerate", avanza = "advance", avanzar = "advance",
      ["por favor"] = "please", ["hasta nuevo aviso"] = "until further notice",
      -- how fast a change is flown ("sube rápido a FL270")
      ["rápido"] = "quickly", rapido = "quickly",
      -- (a waypoint's noun, "add ruta punto ELENA after ARPUG")
      punto = "point",
    },
    -- words of `words` said the same in Portuguese or Italian: no sign of Spanish alone
    -- ("pausa" is Portuguese, Italian and Swedish too)
    -- ("vire" and "cree", "crée" without its accent, are French too)
    shared = { destino = true, crea = true, continua = true, minuto = true, nivel = true, pause = true, vira = true,
      vire = true, cree = true,
      gira = true, carga = true, metros = true, altitud = true, ["rápido"] = true, rapido = true, negativo = true,
      pausa = true, sobre = true, acelera = true, acelere = true, acelerar = true, ["por favor"] = true },
    -- words also English, Portuguese or Italian ("a", "con", "en", "suba"; "quite", English "I'm quite new to
    -- this"): read only in a sentence another word marks Spanish
    joining = { a = "at", al = "to the", la = "the", el = "the", los = "the", las = "the", un = "a", una = "a",
      en = "at", con = "at", y = "and", mil = "thousand", suba = "climb", de = "of", del = "of the",
      quite = "remove", por = "by" },
  },
  french = {
    words = {
      -- instructions and their nouns (the formal imperative, the familiar and the infinitive)
      montez = "climb", monter = "climb", descendez = "descend", descendre = "descend", tournez = "turn",
      tourne = "turn", tourner = "turn", virez = "turn", vire = "turn",
      virer = "turn", prenez = "fly", ["prenez le"] = "fly", prends = "fly", maintenez = "maintain",
      maintiens = "maintain", maintenir = "maintain", ["réduisez"] = "reduce", reduisez = "reduce",
      ["réduis"] = "reduce", reduis = "reduce", ["réduire"] = "reduce", reduire = "reduce",
      augmentez = "increase", augmente = "increase", augmenter = "increase", ["accélérez"] = "increase",
      accelerez = "increase",
      gauche = "left", droite = "right", ["à gauche"] = "left", ["à droite"] = "right",
      ["sur la gauche"] = "left", ["sur la droite"] = "right",
      ["niveau de vol"] = "flight level", ["vitesse verticale"] = "vertical speed",
      ["au niveau"] = "to flight level", ["au niveau de vol"] = "to flight level", ["au cap"] = "heading", pieds = "feet", noeuds = "knots",
      ["nœuds"] = "knots", ["degrés"] = "degrees", degres = "degrees", ["par minute"] = "per minute",
      ["directement"] = "direct", ["direct sur"] = "direct to", ["directement sur"] = "direct to",
      -- the experimenter's commands and courtesy ("pause s'il vous plaît", "accélère fois deux")
      ["s'il vous plaît"] = "please", ["s'il vous plait"] = "please", ["s'il te plaît"] = "please",
      ["s'il te plait"] = "please", ["accélère"] = "speed up", accelere = "speed up",
      fois = "times", supprimez = "delete", supprime = "delete", ["créez"] = "create", creez = "create",
      ["crée"] = "create", cree = "create",
      -- the simulation run by the instructor ("pause la simu", "avance rapide dix minutes", "c'est bon, continue")
      simu = "simulation", ["avance rapide"] = "fast forward", ["c'est bon"] = "okay", continuez = "continue",
      reprenez = "resume", reprends = "resume",
      -- the order of a script's steps ("D'abord ...; ensuite ...; enfin ...")
      ["d'abord"] = "first", ensuite = "then", enfin = "finally",
      -- a Canadian bilingual controller's familiar imperative and rate ("monte 10 000 pieds", "descends taux
      -- 1500", "taux de descente 2000 pieds minute", "taux 2000 en descente"), a value taken back ("heading 180,
      -- non, 170"), and the instructor's ("efface le jazz 7724", "déplace ACA401 à 45.5 -73.5", "ajoute HENRI
      -- ensuite ROSAY", "pause la simulation svp", "on repart", "active la résolution MVP"; "svp" is lexicon.asides')
      descends = "descend", taux = "rate", ["taux de descente"] = "rate of descent",
      ["taux de montée"] = "rate of climb", ["taux de montee"] = "rate of climb", ["en descente"] = "descending",
      ["en montée"] = "climbing", ["en montee"] = "climbing", non = "no", oui = "yes",
      efface = "delete", effacez = "delete", ["déplace"] = "move", deplace = "move", ["déplacez"] = "move",
      deplacez = "move", ajoute = "add", ajoutez = "add", montre = "show", montrez = "show",
      repart = "resume", ["on repart"] = "resume", ["la simulation"] = "the simulation",
      -- (a Belgian or Swiss controller's "virage à droite" and the instructor's "on reprend", "on fait une pause")
      virage = "turn", reprend = "resume", ["on reprend"] = "resume", ["on fait une pause"] = "pause",
      ["on fait une petite pause"] = "pause",
      -- (the Belgian filler "une fois", "..., turn right heading 340, une fois": no count)
      ["une fois"] = "okay",
      ["la résolution"] = "resolution", ["la resolution"] = "resolution",
      -- ("mettez la simulation en pause": put on pause)
      mettez = "put", mets = "put", ["la simulation en pause"] = "the simulation on pause",
      ["la simu en pause"] = "the simulation on pause",
      ["détection de conflits"] = "conflict detection", ["detection de conflits"] = "conflict detection",
    },
    -- words of `words` said the same in English or Spanish: no sign of French alone ("cree" is Spanish, "descends"
    -- English, "non" an English prefix; phrases opening on "en" or "on" mark none, so that Dutch "en" and "met"
    -- stay read after a value: grammar.lua G.dutch_chat_words)
    shared = { vire = true, cree = true, descends = true, non = true, ["en descente"] = true, ["en montée"] = true,
      ["en montee"] = true, ["on repart"] = true, ["on reprend"] = true, ["on fait une pause"] = true,
      ["on fait une petite pause"] = true },
    -- small words, number words, words lexicon.heard_as reads before a value in English ("niveau") and a fix's
    -- name ("monte": "direct monte" is the fix MONTE), read only in a French sentence
    joining = { ["à"] = "to", a = "to", au = "to", le = "the", la = "the", les = "the", et = "and", de = "of",
      du = "of the", ["à la"] = "to", cap = "heading", monte = "climb", niveau = "flight level", vitesse = "speed", dix = "ten",
      vingt = "twenty", trente = "thirty", quarante = "forty", cinquante = "fifty", soixante = "sixty",
      cent = "hundred", cents = "hundred", mille = "thousand" },
  },
  -- German words in a German-speaking controller's English ("sinken flight level one niner zero bitte",
  -- "steigen Sie auf level 250", "neues Flugzeug ..."; "zwo" is their radio "two"; cities by their German
  -- names, read as English names them: "destination Genf" is Geneva's)
  german = {
    -- (written as squawk reads them, its accents taken off: "fünf" is "funf", "Fuß" "fuss"; and with "ue", "oe")
    words = {
      steigen = "climb", ["steigen sie"] = "climb", steigt = "climb", sinken = "descend",
      ["sinken sie"] = "descend", sinkt = "descend", ["steigen auf"] = "climb to", ["steigen sie auf"] = "climb to",
      ["sinken auf"] = "descend to", ["sinken sie auf"] = "descend to", flugflache = "flight level",
      flugflaeche = "flight level", ["drehen sie"] = "turn", drehen = "turn",
      steuerkurs = "heading", geschwindigkeit = "speed", knoten = "knots", fuss = "feet",
      reduzieren = "reduce", ["reduzieren sie"] = "reduce", bitte = "please", danke = "thanks",
      -- (a value said again to confirm it: "heading 350, genau 350", "richtig, two seven zero")
      genau = "correct", richtig = "correct",
      weiter = "continue", ["neues flugzeug"] = "create", loschen = "delete", loeschen = "delete",
      ["loschen sie"] = "delete", ["loeschen sie"] = "delete",
      -- the order of a script's steps ("Zuerst: ... Dann: ... Schliesslich FF 8 Minuten")
      zuerst = "first", dann = "then", schliesslich = "finally",
      -- the clock let run on after a pause ("dann weiter laufen lassen", "weiterlaufen lassen"), or run
      -- ("die Simulation laufen lassen": read as English says "run")
      ["weiter laufen lassen"] = "resume", ["weiterlaufen lassen"] = "resume", weiterlaufen = "resume",
      ["laufen lassen"] = "run",
      -- the experimenter's commands ("Simulation anhalten bitte", "Simulation pausieren", "Konfliktlösung MVP
      -- einschalten") and a rate ("Sinkrate zwotausend", "Steigrate 1500")
      anhalten = "hold", pausieren = "pause", einschalten = "on", ausschalten = "off",
      konfliktlosung = "conflict resolution", konfliktloesung = "conflict resolution",
      konflikterkennung = "conflict detection", sinkrate = "descent rate", steigrate = "climb rate",
      kurs = "heading",
      -- digits ("zwo" for two on the radio)
      eins = "one", zwo = "two", zwei = "two", drei = "three", vier = "four", funf = "five", fuenf = "five",
      sechs = "six", sieben = "seven", acht = "eight", neun = "nine", hundert = "hundred", tausend = "thousand",
      -- (a thousand count said as one word: "Sinkrate zwotausend", "dreitausend Fuss")
      eintausend = "one thousand", zwotausend = "two thousand", zweitausend = "two thousand",
      dreitausend = "three thousand", viertausend = "four thousand", funftausend = "five thousand",
      -- cities by their German names
      genf = "geneva", wien = "vienna", munchen = "munich", muenchen = "munich", koln = "cologne",
      koeln = "cologne", nurnberg = "nuremberg", nuernberg = "nuremberg", mailand = "milan", prag = "prague",
      warschau = "warsaw", brussel = "brussels", bruessel = "brussels", venedig = "venice",
      -- an engineer's typed shorthand ("clh2k kurs 210", "links kurs 090", "20 grad rechts" a relative turn,
      -- "1000 ft höher", "sinkrate 1000", "mit 2000 fpm" its rate, "LAKOL löschen"; "sinkn", "stiegen" as typed)
      kurs = "heading", grad = "degrees", hoher = "higher", hoeher = "higher", tiefer = "lower",
      sinkrate = "rate of descent", steigrate = "rate of climb", mit = "with", sinkn = "descend",
      stiegen = "climb", steig = "climb", und = "and", nein = "no", wegen = "due to", konflikt = "conflict",
      kontakt = "contact", flieger = "aircraft", zeigen = "show", schneller = "faster", langsamer = "slower",
      echtzeit = "real time", zuruck = "back", zurueck = "back", neuer = "new", neue = "new", neuen = "new",
      ["am ende"] = "at the end", ["ans ende"] = "at the end", uberspringen = "skip",
      ueberspringen = "skip", einfugen = "add", einfuegen = "add", raus = "remove", ["aus der route"] = "from the route",
      beide = "both", ja = "yes", hohe = "altitude", hoehe = "altitude", auf = "to", noch = "add", uber = "over",
      ueber = "over",
      -- questions about an aircraft or a place ("was macht X": what X is doing, its state; "wo ist KPT?")
      ["was macht"] = "status of", ["was ist"] = "what is", ["wo ist"] = "where is", wo = "where",
      -- colours of a trail
      rot = "red", gelb = "yellow", grun = "green", gruen = "green", blau = "blue", weiss = "white",
      -- the words of a condition or a sequence between instructions ("sinken FL100 dann dct MUN", "bei KIRDI dann
      -- sinken FL150", "spd 250 bei FL100", "spd 220 bis MORED", "wenn fl250 durch dann spd 300": "durch" is the
      -- level passed, said after it)
      dann = "then", danach = "then", ["und dann"] = "then", ["und danach"] = "then", bei = "at", wenn = "when",
      sobald = "once", bis = "until", durch = "passed", erreicht = "reached", meilen = "miles",
      -- (a controller's and an operator's imperatives and nouns: "dreh rechts um 40 Grad", "Simulation zehn Minuten
      -- vorspulen", "Route anzeigen", "lösche die Hansaline", "verschiebe X nach MANAL", "doppelte Geschwindigkeit",
      -- "auf normale Geschwindigkeit", "Faktor 5", "1000 Fuss pro Minute", "Rate 1000 oder mehr", "bei Erreichen",
      -- "wenn Sie FL250 erreichen", "Mach null komma acht zwo")
      dreh = "turn", drehe = "turn", vorspulen = "fast forward", anzeigen = "show", zeige = "show",
      losche = "delete", loesche = "delete", verschiebe = "move", verschieben = "move", doppelte = "double",
      normale = "normal", faktor = "factor", mehr = "more", erreichen = "reaching", ["bei erreichen"] = "on reaching",
      komma = "point", sekunden = "seconds", zehn = "ten", zwolf = "twelve", zwoelf = "twelve", zwanzig = "twenty",
      dreissig = "thirty", vierzig = "forty", funfzig = "fifty", fuenfzig = "fifty",
    },
    -- words of `words` said the same in Dutch or English: no sign of German alone
    shared = { vier = true, acht = true, wo = true, rot = true, ja = true },
    -- words also English or another language's, read only in a German sentence ("auf", "null" for zero)
    joining = { null = "zero", direkt = "direct", der = "the", die = "the", das = "the",
      -- ("dreh rechts um 40 Grad", "1000 Fuss pro Minute", "Rate 1000 oder mehr", "wenn Sie FL250 erreichen")
      um = "by", pro = "per", oder = "or", sie = "you", minuten = "minutes",
      -- ("ab FL100 dann spd 250": from that level on, the level passed)
      ab = "passing" },
  },
  -- Dutch words in a Dutch or Belgian controller's or sim operator's English ("trails aan graag", "zet hem op tien
  -- keer real time", "gooi KLM886 maar weg", "maak een Transavia aan ...")
  dutch = {
    words = {
      -- instructions and their nouns (the imperative and the infinitive)
      stijg = "climb", stijgen = "climb", daal = "descend", dalen = "descend", draai = "turn", draaien = "turn",
      koers = "heading", vliegniveau = "flight level", snelheid = "speed", knopen = "knots", voet = "feet",
      graden = "degrees", minuten = "minutes", minuut = "minute", seconden = "seconds", naar = "to",
      -- the sim operator's words ("wat doet X": what X is doing, its state)
      pauze = "pause", pauzeer = "pause", pauzeren = "pause", simulatie = "simulation", zet = "set", hem = "it",
      keer = "times", aan = "on", uit = "off", weer = "again", graag = "please", ["doe maar"] = "go ahead",
      maar = "just", verwijder = "delete", verwijderen = "delete", gooi = "delete", weg = "away",
      ["maak een"] = "create a", maak = "create", nieuw = "new", nieuwe = "new", vliegtuig = "aircraft",
      toestel = "aircraft", bestemming = "destination", ["wat doet"] = "status of",
      -- a machine-learning engineer's chat ("X naar fl260 zetten": set X to FL260, "kun je" before it is
      -- grammar.lua G.dutch_chat's; "nou,"
      -- well; "klm12 en tra34 allebei fl320": both; "en bij fl150 spd 250": at that level; "ga maar door":
      -- carry on, the clock let run)
      zetten = "set", nou = "well", allebei = "both", bij = "at", ["ga maar door"] = "continue",
      ["ga door"] = "continue", ipv = "instead of", ["i.p.v."] = "instead of",
      -- (a controller's "ga maar naar heading 100": go on to; "en door, run again": and on; "5 mijl": miles;
      -- "wat is je snelheid?" before "say speed": the same question)
      ["ga maar naar"] = "go to", ["en door"] = "and then", mijl = "miles", ["wat is je snelheid"] = "say speed",
      ["wat is je hoogte"] = "say altitude", ["wat is je koers"] = "say heading",
      -- (said the same in another language, read here: "ja"; "oké", its accent taken off, is also the OKE VOR:
      -- lexicon.asides_alone's)
      ja = "yes",
      -- ("nee", no: the self-correction marker of a Dutch speaker's English, "heading 250, nee, 260")
      nee = "no",
      -- digits and numbers ("vier" and "acht" as in German)
      nul = "zero", twee = "two", drie = "three", vier = "four", vijf = "five", zes = "six", zeven = "seven",
      acht = "eight", negen = "nine", tien = "ten", twaalf = "twelve", twintig = "twenty", dertig = "thirty",
      veertig = "forty", vijftig = "fifty", honderd = "hundred", duizend = "thousand",
      -- (more imperatives and nouns: "vlieg koers 130", "klim naar FL280", "route tonen", "hoogte?", "verder",
      -- "5 minuten vooruit", "drie keer zo snel", "waar is die")
      vlieg = "fly", klim = "climb", tonen = "show", toon = "show", hoogte = "altitude", verder = "continue",
      vooruit = "forward", sneller = "faster", ["waar is"] = "where is", waar = "where",
    },
    -- (and "nee" alone, a habit in English, is no sign that the sentence is Dutch)
    shared = { ja = true, vier = true, acht = true, nee = true },
    -- small words also English or another language's, read only in a Dutch sentence ("pauze even": for a moment)
    joining = { de = "the", het = "the", en = "and", op = "to", van = "of", met = "with", even = "for a moment",
      zo = "as", snel = "fast",
      links = "left", rechts = "right" },
  },
  -- Brazilian Portuguese words in a controller's or student's English ("Gol 1442 turn right proa 300", "descend
  -- nível 100, depois reduce to 220 knots", "heading 075... desculpa, heading 085", "speed 240, tá bom", "cria o
  -- GLO1234 ..."): "proa" is the heading, "nível" the level, "depois" (then) and "e depois" (and then) join two
  -- instructions in order, "tá bom" (all right) asks for nothing. "e" alone (and) and "desculpa" (sorry) are
  -- G.portuguese_and's: "e" read only where no longitude's east can be meant, "desculpa" only before what it
  -- corrects (closing the request it stays the apology it is, accounted's).
  portuguese = {
    words = {
      proa = "heading", ["nível"] = "level", nivel = "level", ["nível de voo"] = "flight level",
      ["nivel de voo"] = "flight level", velocidade = "speed", graus = "degrees", depois = "then",
      ["e depois"] = "and then", ["depois de"] = "after", ["tá bom"] = "ok", ["ta bom"] = "ok", ["está bom"] = "ok",
      ["esta bom"] = "ok",
      -- a Brazilian controller's radio verbs in an English clearance ("desça nível 180", "curva à direita proa 090",
      -- "mantenha 9000", "direto SBGR"; the accents typed or not)
      ["desça"] = "descend", desca = "descend", desce = "descend", descer = "descend", suba = "climb",
      sobe = "climb", subir = "climb", curva = "turn", ["à direita"] = "right", ["a direita"] = "right",
      direita = "right", ["pela direita"] = "right", ["à esquerda"] = "left", ["a esquerda"] = "left",
      esquerda = "left", ["pela esquerda"] = "left", mantenha = "maintain", ["mantém"] = "maintain",
      manter = "maintain", reduza = "reduce", reduzir = "reduce", aumente = "increase", aumentar = "increase",
      direto = "direct", ["direto para"] = "direct to", prossiga = "proceed", rumo = "heading",
      ["pés"] = "feet", pes = "feet", ["velocidade vertical"] = "vertical speed", apague = "delete", remova = "remove",
      -- (the controller's own station named after the callsign: "LATAM 3100, Brasília Centro, bom dia, ...")
      centro = "center", controle = "control", ["aproximação"] = "approach", aproximacao = "approach",
      torre = "tower",
      mova = "move", aguarde = "stand by",
      -- the experimenter's commands ("cria TAM4444 A320 ...", "avança 10 minutes")
      cria = "create", crie = "create", criar = "create", ["avança"] = "advance", avanca = "advance",
      ["avance"] = "advance",
      -- ("mach ponto sete oito", "perfeito, ...", "tempo real", "retomar", "subindo": point, all right, real time,
      -- resume, climbing; "descendo", descending, is also a recogniser's "descend to", read as the verb)
      ponto = "point", perfeito = "ok", ["tempo real"] = "real time", retomar = "resume", subindo = "climbing",
      descendo = "descend",
      -- the simulation switched ("liga conflict detection", "pausa a simulação", "continua a simulacao")
      ["simulação"] = "simulation", simulacao = "simulation", liga = "switch on", ligar = "switch on",
      desliga = "switch off", desligar = "switch off",
    },
    -- words of `words` said the same in Spanish or English: no sign of Portuguese alone
    shared = { nivel = true, ["nível"] = true, avance = true, suba = true, aumente = true, centro = true, torre = true },
    -- ("cria o GLO1234": the article, read only in a sentence another word marks Portuguese; "curve left proa
    -- zero three zero": "curva" said half in English)
    joining = { o = "the", a = "the", curve = "turn" },
  },
  -- Swedish, Norwegian and Danish words in a Scandinavian controller's or sim operator's terse English ("direct
  -- GATMA og descend FL100", "climb FL280 nej FL260", "ta bort DLH2TC", "pausa simuleringen"): "og" and "och"
  -- (and; "och" opening a sentence is the Scots "oh", lexicon.typed_abbreviations') join instructions, "og så"
  -- "and then" (written as squawk reads it, its accents taken off); "nej"/"nei" (no) opens
  -- a self-correction as English "no" does; the courtesy ("tack", "takk", "hej") is lexicon.accounted's
  nordic = {
    words = {
      og = "and", och = "and", ["og sa"] = "and then", ["och sa"] = "and then",
      nej = "no", nei = "no", rattelse = "correction", korrigering = "correction", vanta = "wait",
      -- (the apology that opens a self-correction, as English "sorry": Swedish "förlåt", "ursäkta", Norwegian
      -- "unnskyld", Danish "undskyld")
      forlat = "sorry", ursakta = "sorry", unnskyld = "sorry", undskyld = "sorry",
      -- the sim operator's verbs (Swedish, Norwegian, Danish) and the simulation ("simuleringen": the simulation)
      ["ta bort"] = "remove", radera = "delete", slett = "delete", slet = "delete",
      ["lagg till"] = "add", ["legg til"] = "add", tilfoj = "add", ["tilføj"] = "add",
      pausa = "pause", fortsatt = "continue", fortsett = "continue", ["fortsæt"] = "continue", fortsaet = "continue",
      fortsat = "continue",
      starta = "start",
      simuleringen = "the simulation", simulering = "simulation", simuleringa = "the simulation",
      -- ("og" typed for "of" after a word English follows with "of": "5 miles east og ELTOK", "direct ELTOK instead
      -- og LINSA"; kept as said, asked, never "and")
      ["instead og"] = false, ["east og"] = false, ["west og"] = false, ["north og"] = false, ["south og"] = false,
      ["northeast og"] = false, ["northwest og"] = false, ["southeast og"] = false, ["southwest og"] = false,
      ["route og"] = false, ["out og"] = false, ["ahead og"] = false, ["front og"] = false, ["top og"] = false,
      ["end og"] = false, ["rest og"] = false, ["because og"] = false, ["side og"] = false, ["miles og"] = false,
      ["nm og"] = false, ["km og"] = false,
    },
    -- ("pausa" alone is no sign of a Nordic sentence: Spanish's, Portuguese's and Italian's too; nor are the
    -- English words before "og" typed for "of")
    shared = { pausa = true, ["instead og"] = true, ["east og"] = true, ["west og"] = true, ["north og"] = true,
      ["south og"] = true, ["northeast og"] = true, ["northwest og"] = true, ["southeast og"] = true,
      ["southwest og"] = true, ["route og"] = true, ["out og"] = true, ["ahead og"] = true, ["front og"] = true,
      ["top og"] = true, ["end og"] = true, ["rest og"] = true, ["because og"] = true, ["side og"] = true,
      ["miles og"] = true, ["nm og"] = true, ["km og"] = true },
    -- (words also English or Italian, read only in a Nordic sentence: "från"/"fra" from, "vent" wait)
    joining = { fran = "from", fra = "from", vent = "wait" },
  },
  -- Indonesian and Malay words in a controller's English ("Batik 7151 dan Lion 214 climb FL350", "flight level now
  -- berapa?"): "dan" is "and", "berapa" "how much"; neither marks the sentence (the particles are
  -- accounted's)
  malay = {
    words = { dan = "and", berapa = "how much", ke = "to", ketinggian = "altitude" },
    shared = { dan = true, berapa = true },
    joining = {},
  },
  -- Greek words in a Greek or Cypriot speaker's English, romanised as typed ("climb at 200 kai reduce at 220
  -- knots", "descend at 280, meta turn right", "endaxi, continue", "climb at 130, ochi, at 120"): "kai" (and) and
  -- "meta" (then, after) join instructions in order, "endaxi" (all right) asks for nothing, "ochi"/"oxi" (no)
  -- opens a self-correction as English "no" does. None marks the sentence ("meta" and "ne" are English words or
  -- codes too; "ne", yes, is left to lexicon.accounted's readings). The thanks ("efcharistó") is accounted's.
  greek = {
    words = { kai = "and", meta = "then", ["kai meta"] = "and then", endaxi = "okay", entaxi = "okay",
      endaksi = "okay", entaksi = "okay", entaxei = "okay", ochi = "no", oxi = "no", ["όχι"] = "no" },
    shared = { kai = true, meta = true, ["kai meta"] = true, endaxi = true, entaxi = true, endaksi = true,
      entaksi = true, entaxei = true, ochi = true, oxi = true, ["όχι"] = true },
    joining = {},
  },
  -- Russian words in a Russian-speaking (or Kazakh, Uzbek) controller's English, transliterated as typed ("UTair 457
  -- izvinite, turn left ...", "descend flight level 70 izvinite 60", "khorosho, climb ...", "direct OKBIT ponyal?"):
  -- "izvinite"/"prostite" (sorry, excuse me) open a correction or an apology as English "sorry" does, "khorosho"/"ladno"
  -- (all right) ask for nothing, "ponyal"/"ponyatno" (understood) is the check a clearance closes with. None marks the
  -- sentence. "da" (yes) and "net" (no) are English words or codes elsewhere too: G.russian_yes_no reads them where
  -- they are set off.
  russian = {
    words = { izvinite = "sorry", izvini = "sorry", prostite = "sorry", prosti = "sorry", khorosho = "okay",
      horosho = "okay", harasho = "okay", khorasho = "okay", ladno = "okay", ponyal = "understood",
      ponyala = "understood", ponyali = "understood", ponyatno = "understood" },
    shared = { izvinite = true, izvini = true, prostite = true, prosti = true, khorosho = true, horosho = true,
      harasho = true, khorasho = true, ladno = true, ponyal = true, ponyala = true, ponyali = true, ponyatno = true },
    joining = {},
  },
  -- Polish words in a Polish speaker's English ("LOT1LC speed 230 i potem heading 200", "speed 300, nie, 290", "climb
  -- on 240, przepraszam, 230", "ok, dobrze, continue"): "potem" and "i potem"/"a potem" (then, and then) join
  -- instructions in order, "nie" (no) and "przepraszam" (sorry, excuse me) open a self-correction as English "no"
  -- and "sorry" do (closing the request, an apology), "dobrze" (all right) asks for nothing. None marks the
  -- sentence; "tak" (yes), "proszę" and "dzięki" are accounted's.
  polish = {
    words = { potem = "then", ["i potem"] = "and then", ["a potem"] = "and then", nie = "no",
      przepraszam = "sorry", dobrze = "okay" },
    shared = { potem = true, ["i potem"] = true, ["a potem"] = true, nie = true, przepraszam = true, dobrze = true },
    joining = {},
  },
  -- Italian words in an Italian speaker's English ("Alitalia 1712 velocità 260 e poi quota 260", "turn at prua 200",
  -- "climb at 350, no scusa, 370", "allora, restart", "sì, ...", "va bene"): "velocità" is the speed, "prua" the
  -- heading, "poi" and "e poi" (then, and then) join instructions in order, "scusa" (sorry) opens a self-correction
  -- as English "sorry" does, "allora" (so, well), "sì" (yes) and "va bene" (all right) ask for nothing. None marks
  -- the sentence; "e" alone is G.portuguese_and's, "quota" lexicon.heard_as's, "grazie" accounted's.
  italian = {
    words = { ["velocità"] = "speed", velocita = "speed", prua = "heading", poi = "then", ["e poi"] = "and then",
      scusa = "sorry", ["scusami"] = "sorry", allora = "so", ["sì"] = "yes", si = "yes", ["va bene"] = "okay",
      -- (an Italian controller's "scusi" between two values is the correction's "sorry": "turn right heading 360,
      -- scusi, 340"; "un attimo" a moment; "riprendiamo" the run resumed)
      scusi = "sorry", scusate = "sorry", ["mi scusi"] = "sorry", ["un attimo"] = "one moment",
      ["un momento"] = "one moment", riprendiamo = "resume", riprendi = "resume",
      -- ("descenda livello one six zero": the level; "livello di volo" the flight level)
      livello = "level", ["livello di volo"] = "flight level" },
    shared = { ["velocità"] = true, velocita = true, prua = true, poi = true, ["e poi"] = true, scusa = true,
      scusami = true, allora = true, ["sì"] = true, si = true, ["va bene"] = true, scusi = true, scusate = true,
      ["mi scusi"] = true, ["un attimo"] = true, ["un momento"] = true, riprendiamo = true, riprendi = true,
      livello = true, ["livello di volo"] = true },
    joining = {},
  },
  },
  -- digits said in Spanish, Portuguese or French by a controller speaking English ("Avianca cero one nine",
  -- "Iberia tres uno seis seis", "Azul quatro zero cinco zero"; Brazilian "meia" is six): that digit
  -- only beside another digit, said or typed, of either language, or a spelled letter ("tres" alone stays
  -- a word)
  foreign_digits = { cero = "zero", uno = "one", dos = "two", tres = "three", ["três"] = "three",
    cuatro = "four", cinco = "five", seis = "six", siete = "seven", ocho = "eight", nueve = "nine",
    dois = "two", duas = "two", quatro = "four", meia = "six", sete = "seven", oito = "eight",
    nove = "nine",
    -- and Italian ("Itarrow tre uno quattro"; "uno", "nove" as in Spanish and Portuguese; "due" (two) only between
    -- two digits or beside another of these words, foreign_digits_flanked: English "due traffic" follows a value)
    tre = "three", quattro = "four", cinque = "five", sei = "six", sette = "seven", otto = "eight",
    -- and French ("France Soleil quatre un deux zero"; "six" and "zero" as in English)
    un = "one", deux = "two", trois = "three", quatre = "four", cinq = "five", sept = "seven", huit = "eight", neuf = "nine",
    uma = "one" },
  foreign_digits_flanked = { due = "two" },
  -- French said inside an English clearance by a Moroccan, Algerian or Tunisian speaker (grammar.lua
  -- G.french_in_english): a number said in French words ("cap deux cent quatre-vingt-dix", "vitesse trois cent
  -- trente") is its digits when the words make one number by French's rules and hold a word of tens, hundreds
  -- or thousands (digits said one by one, "quatre un deux", are foreign_digits'); "et" (and) between two parts of
  -- a request, never before a value it could be "at" of ("speed 250 et FL100" stays asked)
  french_in_english = {
    units = { un = 1, une = 1, deux = 2, trois = 3, quatre = 4, cinq = 5, six = 6, sept = 7, huit = 8, neuf = 9 },
    teens = { dix = 10, onze = 11, douze = 12, treize = 13, quatorze = 14, quinze = 15, seize = 16 },
    tens = { vingt = 20, trente = 30, quarante = 40, cinquante = 50, soixante = 60 },
    -- ("et puis": and then; "et" alone: and)
    joins = { ["et puis"] = "and then", et = "and" },
    -- ("speed 250 until FL200 and after 300 knots": "et après", and afterwards, before a speed said with its unit)
    afterwards = { knots = true, knot = true, kts = true, kt = true },
  },
  -- Portuguese "um" (one), a hesitation in English: one only inside a run of digit words holding one of
  -- foreign_digits ("nível três um zero"); "three um zero" keeps its hesitation
  foreign_hesitation_digits = { um = "one" },
  -- words speech recognition writes for a digit said inside a callsign ("wizzair to lima papa" is WZZ2LP,
  -- "lufthansa for hundred" DLH400, "europa oh five one" AEA051, "air india one not one" AIC101, "nought" said
  -- for zero): that digit only where the callsign so
  -- read is exactly one aircraft's (grammar.lua homophone_ids)
  digit_homophones = { to = "two", too = "two", ["for"] = "four", fore = "four", won = "one", ate = "eight", sex = "six",
    oh = "zero", nought = "zero", naught = "zero", ["not"] = "zero" },
  -- everyday words the callsign matcher also reads as a flight number's last digit after its other digits
  -- (references.cpp heard_digit: "easy eight on descend" for EZY81): the word -> the digit. Read so the callsign
  -- is confirmed, never taken (handlers.lua m:homophone_closing); "for", "to", "won" closing one stay read, as
  -- R42's rows expect.
  closing_homophones = { on = "1", a = "8" },
  -- verbs that open a creation ("create", "make a cactus 1496 ..."): an airline's telephony run into its
  -- number after one is the new aircraft's id (grammar.lua glued_telephony)
  creation_verbs = { create = true, creat = true, cre = true, spawn = true, generate = true, make = true },
  -- verbs that start, stop or restart the run or an aircraft's navigation: one no instruction was read from is a
  -- leftover, asked about (grammar.lua G:unaccounted), never set aside
  clock_verbs = { resume = true, unpause = true, unfreeze = true, restart = true },
  -- nouns naming the place said after a word of a place's slot ("add waypoint rosig", "direct to the fix
  -- kudes"): the slot goes on over them, and over "the" before one (grammar.lua typed_places)
  place_nouns = { waypoint = true, wpt = true, fix = true, point = true },
  -- words that are parts of a number said in words besides the number words themselves: a zero ("oh", "o") and
  -- a digit said twice or three times ("double", "triple"); a word joined by hyphens of these and number words
  -- only is a number said ("six-oh-seven", "one-double-zero"; grammar.lua G.number_words_apart)
  hyphen_number_parts = { oh = true, o = true, double = true, triple = true },
  -- tens words, which join the unit digit after them into one number
  tens = { "twenty", "thirty", "forty", "fourty", "fifty", "sixty", "seventy", "eighty", "ninety" },
  -- words speech recognition writes for a spoken "two" before digits
  two_heard = { "to", "too", "t" },
  -- units a value said after an airline name carries ("turn the Ryanair 20 degrees", "move the Ryanair 20
  -- nautical miles south"): no flight number
  value_units = { degrees = true, degree = true, knots = true, knot = true, kts = true, feet = true, ft = true,
                  percent = true, nm = true, nautical = true, miles = true, mile = true, km = true },
  -- verbs of a relative value said between an airline's name and a number with one of value_units ("let the Condor
  -- turn 45 degrees right"), and words that may stand before them ("the Lufthansa now climb 2000 feet"): the
  -- number is the value, no flight number (grammar.lua airline_values)
  airline_value_verbs = { turn = true, climb = true, descend = true, reduce = true, increase = true, slow = true,
                          accelerate = true, decelerate = true, veer = true, offset = true },
  airline_value_leads = { now = true, please = true, immediately = true },
  -- airlines' telephony that is also the noun of a value, word -> {ICAO prefix, the noun's plain word}: before
  -- a number and its unit, or after one of value_noun_before with none of the airline flying, it is that noun
  -- ("VLG12AB velocity 250 knots", "reduce the velocity"; grammar.lua airline_values)
  value_noun_airlines = { velocity = { "VOZ", "speed" } },
  value_noun_before = { the = true, a = true, your = true, its = true, his = true, her = true, their = true },
  -- speed units that may stand apart from their number ("two one zero, knots")
  -- informal verbs of changing a value ("bump it to 280 knots", "crank it up to Mach .80"): a speed when a
  -- speed's unit follows them (rules.lua)
  informal_value_verbs = { "bump", "crank", "push", "knock" },
  speed_units = { "knots", "knot", "kts", "kt", "knts", "kits" },  -- ("250 kits": kts typed with a slip)
  -- an intruder set up against an aircraft (CRECONFS): the nouns that name it, and the words before
  -- or after its closest approach, its loss of separation and a head-on course
  intruder = { "intruder", "conflict", "conflicting", "converger" },
  -- encounters an instruction to traffic flying brings about ("to create a crossing", "make the conflict a near
  -- miss"): no aircraft created
  encounters_made = { "conflict", "crossing", "encounter", "miss", "collision", "situation", "convergence" },
  closest_approach = { "cpa", "miss", "passing", "closest" },
  loss_of_separation = { "los", "tlos", "tlosh", "loss" },
  head_on = { "head-on", "head" },
  -- what two aircraft swap ("swap the levels of KLM12 and TRA6021"), by the command that sets it (the
  -- spelling fixer makes "headings" "heading")
  swapped = { levels = "ALT", level = "ALT", altitudes = "ALT", altitude = "ALT", headings = "HDG", heading = "HDG",
              speeds = "SPD", speed = "SPD" },
  -- a new aircraft placed along another's track ("20 nm ahead of KLM12", "dead behind KL001 at 15 nm"):
  -- the side, as a bearing off that aircraft's heading [deg]; its course then said against that
  -- aircraft's: the reverse ("head-on", "opposite direction", "coming the other way", "reciprocal") or the
  -- same ("same heading", "same track"); its level and speed by a difference ("1000 ft above", "30 kt faster")
  along_track = { ahead = 0, behind = 180, front = 0 },  -- ("in front of")
  -- whom a note is for when it is the speaker's own ("note to self:", "note for me:"), not the log's
  note_to_self = { "self", "myself", "me" },
  ownship = { "ownship", "own-ship" },
  course_reversed = { "head-on", "opposite", "reciprocal", "other" },
  course_nouns = { "heading", "hdg", "direction", "track", "course", "way" },
  faster = { "faster", "quicker" },
  slower = { "slower" },
  -- the clock reaching a time ("when the clock hits 45 minutes")
  clock_reaches = { "hits", "hit", "reaches", "reach", "shows" },
  -- the words between "once"/"when" and the level or place reached ("when it's level", "once he's there", "when
  -- they get there": G:reached_opening)
  reached_subjects = { "it", "you", "he", "she", "they" },
  reached_verbs = { "is", "it's", "you're", "he's", "she's", "they're", "are", "gets", "get" },
  -- the commands that take a time said (seconds; G:uncarried): a time is carried by one of their numbers only
  time_commands = { "DELAY", "FF", "DT", "DTLOOK", "CRECONFS", "TRAIL" },
  -- [s] the least fast-forward read from "ff" and a number with no unit ("ff 30", "ff 300"); below it ("ff 5",
  -- "ff 20") the number is as likely minutes with the unit left out, and the unit is asked
  ff_bare_min_s = 30,
  -- a wait said before an instruction (handlers' at_time, DELAY): the verbs that say it ("wait 60 seconds then
  -- ...", "wait for 2 minutes and ...", "after waiting a minute"), the verbs said with an object before the time
  -- ("give it sixty seconds and then ...", "allow him 2 minutes, then ...") and those objects, the words that join
  -- a verb's wait to the instruction after it (one is needed: "wait a minute, turn ..." may be "hold on", asked),
  -- and the words that say the time has run ("once 90 seconds have passed", "when 2 minutes are up")
  wait_verbs = { "wait", "waiting" },
  wait_giving = { "give", "allow", "allowing" },
  wait_objects = { "it", "him", "her", "them", "us", "that", "this" },
  wait_joins = { "then", "and", "before" },
  wait_run = { "passed", "elapsed", "gone", "over", "up" },
  -- words of an amount said loosely between the wait's word and its time in words ("in about a minute", "give it
  -- just a minute"): such a wait is asked, never read or dropped
  -- the words of time said between the verb and "doing" in an indirect question ("tell me what KLM12 is
  -- currently doing"): the question is about now, which is what squawk shows
  -- verbs of a request to be told something ("tell me the destination of EIN655", "let me know the origin")
  -- the modal verbs that open a polite question asking for an instruction ("could you please resume the run?")
  polite_openings = { "could", "can", "would", "will" },
  -- longer openings of a polite request that an aircraft named next is to act on (grammar.lua G:request_opening:
  -- "would it be possible to have the Porter, once it reaches OAKVL, turn ...", "I wonder if the Jazz, once ...")
  request_openings = { "would it be possible to have", "would it be possible for", "is it possible to have",
      "is it possible for", "could you have", "could you get", "can you have", "can you get", "would you have",
      "i wonder if", "i was wondering if", "we wonder if", "we were wondering if",
      -- (a wish said as an East African speaker says it, "I want that the Qatari, after it pass KOBAB, descend
      -- FL250": "want" and "that" or not; a longer form before the shorter it opens with)
      "i want that", "we want that", "i want", "we want",
      -- ("please let the Austrian, when it passes NAPSA, descend ...", "for the Air Do, when ...": "let" or "for"
      -- before the aircraft that is to act, courtesy before it or not)
      "kindly let", "please let", "let", "for" },
  -- the first words of a note's text that make it a question of its own ("... saying are you ready?"): its closing
  -- "?" may be the note's or the request's (handlers_other.lua m:echo)
  echo_question_openers = { "who", "what", "where", "when", "why", "how", "which", "is", "are", "am", "was", "were",
      "do", "does", "did", "have", "has", "can", "could", "will", "would", "shall", "should", "may" },
  -- the names of the simulation's settings before a verb that changes them ("the look-ahead should be reduced
  -- to two minutes")
  setting_nouns = { "ahead", "lookahead", "look-ahead", "dtlook", "radius", "zoner", "zonedh", "zone", "height",
      "multiplier", "dtmult" },
  told_me_verbs = { "tell", "show", "give", "remind", "let" },
  -- a comma written, as German, Dutch and Scandinavian punctuation requires, between a verb of telling or knowing
  -- and the question clause it opens ("Could you tell me, on which flight level the A320 is?", "I would like to
  -- know, which speed the Condor flies"): the verbs (with "me" or "us" after them, or alone) and the words that
  -- open the clause, and the prepositions said before "which" ("on which"); the comma is no break between two
  -- requests (sets)
  clause_comma_verbs = { tell = true, say = true, show = true, know = true, explain = true, ask = true, see = true,
    check = true },
  clause_comma_openers = { which = true, what = true, where = true, when = true, whether = true, how = true,
    ["if"] = true, who = true, why = true },
  clause_comma_prepositions = { on = true, at = true, ["in"] = true, with = true, to = true, from = true,
    ["for"] = true, by = true, over = true },
  indirect_question_adverbs = { "currently", "now", "presently", "still", "actually", "just" },
  -- words said loosely before a value ("to like four times", "about 4x", "around 3 times"): the value said is
  -- the one used
  value_hedges = { "like", "about", "around", "roughly", "approximately", "maybe" },
  -- how much faster the run is wished, said between "speed it up" and its factor ("speed the sim up heaps, like times
  -- ten", "speed it up a lot, 4x"): the factor said is the rate
  speedup_degrees = { "heaps", "lots", "loads", "lot", "bit", "a" },
  wait_hedges = { "about", "around", "roughly", "approximately", "nearly", "almost", "just", "maybe" },
  -- a time said in words the quantities do not read (G:spoken_durations): one unit after "a" or "an" ("a minute",
  -- "an hour and a half", "half a minute", "a quarter of an hour"; seconds each, lexicon.fractions for the parts),
  -- and the loose ones, asked for a time wherever they say a wait: a count that is no number ("a couple of
  -- minutes", "a few minutes", "several minutes"), a unit "or two" ("a minute or two", "a minute or so"), or a
  -- while of no length ("a moment", "a bit", "a sec", "a second": "wait a second" is "hold on")
  spoken_units = { minute = 60, minutes = 60, min = 60, mins = 60, hour = 3600, hours = 3600 },
  loose_counts = { "couple", "few", "several" },
  loose_whiles = { "moment", "bit", "while", "sec", "second", "seconds", "secs" },
  -- more of the same ("3 more random ones")
  more = { "more", "extra", "new" },
  -- the performance models PERF selects, by the words that name them ("the simple class-based model")
  perf_models = { openap = "OPENAP", class = "CLASS", classes = "CLASS", legacy = "CLASS", simple = "CLASS" },
  -- the colours TRAIL acid accepts
  trail_colours = { "blue", "red", "yellow" },
  -- what a controller acknowledges or refuses beside an instruction, set aside with no command of its own
  -- (G:acknowledged, G:refused); accounted for only there ("Mayday" or "deviation" anywhere else asks):
  acknowledged = {
    -- a distress or urgency call, acknowledged before it ("roger Mayday", "copy your pan pan", "roger the
    -- emergency") or after it ("Mayday acknowledged", "pan pan received")
    calls = { "mayday", "pan", "emergency" },
    before = { "roger", "copy", "copied", "understood", "acknowledge" },
    articles = { "the", "your" },
    after = { "acknowledged", "received", "copied", "understood", "noted" },
    -- a request granted, said whole and ending its clause ("emergency descent approved, descend ...",
    -- "deviation approved, when able proceed direct BRISS")
    granted = { { "emergency", "descent", "approved" }, { "deviation", "approved" }, { "deviations", "approved" } },
    -- what "unable" refuses, said after it with "that", "the", "your" or "this" or alone ("unable that heading",
    -- "unable higher"); "unable" is the pilot's own after these words ("if unable", "advise when unable")
    refused = { "heading", "level", "altitude", "speed", "request", "routing", "route", "climb", "descent", "turn",
      "shortcut", "higher", "lower" },
    refused_articles = { "that", "the", "your", "this" },
    pilots = { "if", "when", "you", "you're", "are", "not" },
  },
  -- a terse typed list of an aircraft's values ("hop7 6000 hdg 220 230kt"): `labels`, words before a value that
  -- name it; `units`, words after it (or glued to it) that name it; `level`, labels and units of a level (one
  -- said makes a bare number no level of its own); `joins`, words between the values. A bare number there of
  -- hundreds of feet in four or five figures is the level (G.terse_altitude)
  terse_list = {
    labels = { "hdg", "heading", "h", "spd", "speed", "s", "vs", "roc", "rod", "mach", "m", "l", "r", "lt", "rt",
      "left", "right", "lft", "rgt" },
    units = { "kt", "kts", "knots", "fpm", "deg", "degs", "degrees" },
    level = { "fl", "alt", "altitude", "level", "lvl", "ft", "feet", "climb", "descend", "desc", "clb", "dsc",
      "squawk", "sq", "code", "xpdr", "transponder" },
    joins = { "and", "," },
    -- (the labels and unit of a rate: a bare number straight after its value is no level, G.terse_altitude)
    rate = { "vs", "roc", "rod", "fpm" } },
  -- the letters of an experiment's ids typed glued to their figures as a label before a colon ("t2:", "sess4:"),
  -- beside lexicon.aside.study_labels ("exp1:", "run3:"); any other letters make such a label only before an
  -- aircraft that flies (G.id_label)
  id_labels = { "t", "ex", "ev", "sess", "task", "item", "part", "p" },
  -- resolution methods said in words
  mvp = { "mvp", "voltage", "potential" },
  -- abbreviations a recogniser may spell letter by letter ("f l one two zero"), beside the words of
  -- not_names and not_simulated; the navaid kinds a limit or a place names ("till four d m e", "the o b k v o r")
  spelled = { "fl", "mvp", "dme", "vor", "ndb" },
  -- a city's other name -> the name the navdata gives its navaids, read before a navaid's kind ("direct Bombay VOR":
  -- MUMBAI VOR-DME, BBB; "the Bengaluru VOR": BANGALORE VOR-DME, BBG); airports keep their own names (airport_names)
  navaid_city_names = { bombay = "mumbai", madras = "chennai", calcutta = "kolkata", bengaluru = "bangalore" },
  -- the words of a navaid's kind that such a name is read before
  navaid_kind_words = { "vor", "ndb", "dme", "vordme", "vortac", "beacon" },
  -- spellings of a word's first sound (a Lua pattern at the word's start, the letter it sounds as), tried in order:
  -- a fix heard by a recogniser keeps its first sound, not always its first letter ("cubs" for KUBBS, "fil" for PHIL)
  first_sounds = { { "^ph", "f" }, { "^c[eiy]", "s" }, { "^c", "k" }, { "^q", "k" }, { "^kn", "n" }, { "^wr", "r" } },
  -- words of an altimeter setting: an altitude said with one is a level above the sea, no change by
  -- that much ("descend 3000 feet QNH 1008")
  altimeter = { "qnh", "altimeter", "qfe" },
  -- units that make an altitude a level in feet
  feet = { "ft", "feet", "foot" },
  -- units that make an altitude a level in metres (the quantity's value is already in feet)
  metres = { "m", "metres", "meters", "metre", "meter" },
  -- words that restate a level in another unit ("9200 metres, that is flight level 301", "which is")
  restating = { "that", "thats", "is", "which", "ie", "i.e", "equals", "meaning" },
  vertical = { "vertical", "height", "zonedh", "dh", "hpz" },
  zone_radius = { "radius", "zoner" },
  -- bare nouns naming what to show, after a handled instruction
  shown = { "altitude", "speed", "heading", "airspeed" },
  -- units after "step N" that make it the simulation's time step, never a protocol's step label (set)
  step_units = { s = true, sec = true, secs = true, second = true, seconds = true, ms = true, hz = true,
    min = true, mins = true, minute = true, minutes = true },
  -- short German and Dutch asides of acknowledgement ("ist gut, ...", "..., alles klar", "goed zo"): accounted for
  -- only where one stands alone in its clause (the request's edge or punctuation on both sides, fillers between);
  -- after a value ("hdg 180 ist gut, just ...") it says the value is fine, which is asked
  -- a transcriber's mark that words were not heard, in brackets, parentheses, angle brackets or asterisks
  -- ("[unintelligible]", "(garbled)", "<inaudible>"): the request is asked again, never read without them
  -- (grammar.lua M.translate)
  unheard_markers = { "unintelligible", "inaudible", "garbled", "unreadable", "indistinct", "incomprehensible",
    "crosstalk", "cross-talk", "blocked", "muffled", "mumbled", "mumbling", "unclear", "cut off", "cut out",
    "not heard", "unheard", "illegible", "static" },
  asides_alone = { "ist gut", "alles gut", "alles klar", "passt", "passt so", "sehr gut", "na gut", "gut", "prima",
    "genau", "jawohl", "vielen dank", "danke schon", "dankeschon", "is goed", "goed zo", "in orde", "mooi", "oke",
    "klopt", "okidoki",
    -- a South African instructor's sympathy ("Ag shame, ...", "..., ag shame, turn right ...") and a break named
    -- beside a pause ("Pause the exercise, tea break")
    "ag shame", "shame", "eish",
    -- and approval ("..., lekker", "ok lekker, run": nice, good; "heading 080 lekker" after a value is asked)
    "lekker", "tea break", "coffee break", "lunch break", "comfort break",
    -- Korean and Mandarin hesitations said in English between commas ("..., eo, descend", "..., nage, reduce"):
    -- Korean "eo", "eum", "geu", "jeo" (uh, that); Mandarin "en", "nage", "zhege" (um, that), "hao", "dui" (ok,
    -- right)
    "eo", "eum", "geu", "jeo", "en", "nage", "zhege", "hao", "dui" },
}
