:- module(oro_parse,
          [ oro_tokenize/3,             % +Text, +Delimiter, -Tokens
            oro_clean_value/2,          % +Text, -String
            oro_parse_collection/3,     % +Kind, +Text, -Elements
            oro_parse_map/2,            % +Text, -Pairs
            oro_parse_statement/2,      % +Text, -Triple
            oro_parse_statements/2,     % +Texts, -Triples
            oro_is_partial/1,           % +Triple
            oro_statements/3,           % +Statements, -Triples, -Bindings
            oro_complete_statements/2,  % +Statements, -Triples
            oro_parse_budget/1          % :Goal
          ]).
:- use_module(library(semweb/rdf_db)).
:- use_module(library(error)).
:- use_module(library(lists)).
:- use_module(library(apply)).
:- use_module(library(settings)).
:- use_module(library(oro/oro_names)).

:- meta_predicate
    oro_parse_budget(0).

/** <module> Parsing of ORO request parameters and statements

This module decodes the text of request parameters as oro-server 0.8.2
does (ORO-SPEC §2) and turns statement texts into rdf_db triples (§4.2,
§4.3).  Everything here is pure: no predicate touches the store, so a
batch that fails half-way has nothing to undo.

  - oro_tokenize/3 is ORO's tokenizer: it splits on a delimiter only
    outside `[ ]`, `{ }` and quotes, keeping empty tokens.
  - oro_clean_value/2 is ORO's `cleanValue`: trim, drop one outer pair
    of quotes, Java-unescape.
  - oro_parse_collection/3 and oro_parse_map/2 decode `[a, "b"]` and
    `{k:v}` parameters into lists of strings.
  - oro_parse_statement/2 turns `subject predicate object` into
    `rdf(S, P, O)`, where each position is an IRI, an rdf_db literal term
    (objects only) or `var(Name)` for a `?name` token.

Object tokens follow ORO's literal rules: `true`/`false` are booleans,
quoted text is an `xsd:string`, `[+-]?[0-9]+` is an `xsd:int`, decimal and
exponent forms are `xsd:double`, `lex^^type` is a typed literal whose
lexical form is checked against the XSD datatype, `"text"@lang` is a
language-tagged literal, anything else is a resource.  Lexical forms are
kept as written, as atoms.

Errors are ISO-shaped, `error(Formal, _)`:

  | Formal                                        | raised for                       |
  |-----------------------------------------------|----------------------------------|
  | `type_error(oro_collection, Text)`            | a set/list not framed by `[ ]`   |
  | `type_error(oro_map, Text)`                   | a map not framed by `{ }` or an entry without `:` |
  | `syntax_error(oro_unicode_escape(Text))`      | a malformed `\uXXXX` escape      |
  | `syntax_error(oro_statement_tokens(N, Stmt))` | a statement without 3 tokens     |
  | `syntax_error(oro_statement_empty_token(Stmt))` | 3 tokens, one of them empty (two spaces) |
  | `syntax_error(oro_statement_variable(Stmt))`  | a bare `?` token                 |
  | `type_error(oro_statement, Stmt)`             | a token with an unterminated quote (`a b "c`), or an object opening with a quote that is no literal (`"a"b`) |
  | `syntax_error(oro_invalid_datatype(Type))`    | an unknown `xsd:` datatype, or an empty one |
  | `syntax_error(oro_lexical_form(Lex, Type))`   | a lexical form its datatype rejects |
  | `syntax_error(oro_statement_literal(Stmt))`   | a literal object of a predicate that needs a resource (oro_complete_statements/2) |
  | `syntax_error(oro_statement_name(Token))`     | a name with a bracket or brace (`[[a]]`) outside `<...>` |
  | `resource_error(oro_nesting(Max))`            | brackets or braces nested deeper than the `max_nesting` setting |
  | `resource_error(oro_parse_limit(Limit))`      | a request whose parsing ran past the `inference_limit` setting |

Texts inside error terms are strings.

## Speed

Parsing is on the path of every request, so the common case is kept to
a few C-level scans per text.  A text with none of the characters the
tokenizer and `cleanValue` track (quotes, brackets, braces, backslash,
control characters; see plain_text/1) is split with split_string/4
directly: a set of such statements, an unquoted statement and the
names in it take this *fast path*.  So does a set whose elements are
all quoted with one quote, as liboro and pyoro send them
(quoted_elements/2), and a set of unquoted statements with a quoted
label in it (one_quote_elements/2).  Other texts are tokenized from one
tracked character to the next, found by split_string/4, the plain text
between them split at once (scan_tokenize/3); the general, code-by-code
path is left for texts with NUL.  All give the same results
(test/test_parse.pl runs them over corpora of tricky and random
inputs); a fast path only skips work that provably does nothing on the
texts it takes.

## Bounded cost

Every text costs time and memory in proportion to its length, with a
small constant (bench/bench_parse.pl measures the worst constructs and
README's limits table gives the figures):

  - Texts are scanned in chunks of chunk_chars/1 characters
    (one_part/2, scan_tokenize/3), so a text full of tracked characters
    does not make one string per character before anything is
    decided.
  - The depth of `[ ]` and of `{ }` the tokenizer tracks is limited
    by the setting `max_nesting` (default 32; ORO's parameters nest 2
    deep): past it, `resource_error(oro_nesting(Max))` is raised as soon
    as the scan reaches it, within the first chunk of a text of nested
    brackets however long.
  - A name never holds a bracket or a brace outside `<...>`
    (`syntax_error(oro_statement_name(Token))`): `[[[x]]]` is not
    stored as a name.
  - The parsing of one request has a CPU budget, counted in Prolog
    inferences so that it does not depend on the machine's load: the
    setting `inference_limit` (default 50,000,000, which the costliest
    constructs spend in 14 s of CPU on the project's VM and plain
    statements in 5 s; 0 for none).  oro_parse_budget/1 opens the
    request's budget, and every public predicate of this module given
    a text of 64 Ki characters or more spends from it (texts below that
    cost a few milliseconds at most).  Past it,
    `resource_error(oro_parse_limit(Limit))` is raised.
*/

:- setting(max_nesting, positive_integer, 32,
           'Deepest nesting of [ ] and of { } a request parameter may have').
:- setting(inference_limit, nonneg, 50000000,
           'Inferences the parsing of one request may take (a CPU budget \c
            that does not depend on the load: 50,000,000 is 2-14 s of \c
            CPU); 0 for no limit').

%   chunk_chars(-N): texts are scanned N characters at a time.
%   budget_chars(-N): a public predicate given a text of N characters
%   or more spends from the parse budget.

chunk_chars(16384).
budget_chars(65536).

%!  oro_parse_budget(:Goal) is semidet.
%
%   Run Goal once with a parse budget of its own: the parsing done by
%   the predicates of this module within Goal takes at most the
%   `inference_limit` setting in all (the server runs each request
%   so).  Outside such a Goal each public call has the whole limit.
%
%   @error resource_error(oro_parse_limit(Limit)) if the parsing within
%          Goal takes more.

oro_parse_budget(Goal) :-
    setting(inference_limit, Limit),
    (   nb_current(oro_parse_left, Old)
    ->  true
    ;   Old = none
    ),
    setup_call_cleanup(nb_setval(oro_parse_left, Limit),
                       once(Goal),
                       restore_budget(Old)).

restore_budget(none) :-
    !,
    nb_delete(oro_parse_left).
restore_budget(Old) :-
    nb_setval(oro_parse_left, Old).

%   bounded(+Size, :Goal): run Goal once, the parse of texts of Size
%   characters in all, within what is left of the parse budget when
%   Size is budget_chars/1 or more (call_with_inference_limit/3, which
%   costs no thread switch).

bounded(Size, Goal) :-
    budget_chars(Min),
    (   Size < Min
    ->  call(Goal)
    ;   setting(inference_limit, Limit),
        Limit > 0
    ->  (   nb_current(oro_parse_left, Left0)
        ->  Left = Left0
        ;   Left = Limit
        ),
        statistics(inferences, I0),
        (   Left =< 0
        ->  Result = inference_limit_exceeded
        ;   call_with_inference_limit(once(Goal), Left, Result)
        ),
        (   Result == inference_limit_exceeded
        ->  throw(error(resource_error(oro_parse_limit(Limit)), _))
        ;   nb_current(oro_parse_left, _)
        ->  statistics(inferences, I1),
            Left1 is Left - (I1-I0),
            nb_setval(oro_parse_left, Left1)
        ;   true
        )
    ;   call(Goal)
    ).

texts_size(Texts, Size) :-
    foldl(add_text_size, Texts, 0, Size).

add_text_size(Text, Size0, Size) :-
    (   text(Text)
    ->  atom_length(Text, Length),
        Size is Size0 + Length
    ;   Size = Size0
    ).

text(Text) :-
    (   string(Text)
    ->  true
    ;   atom(Text)
    ).

nesting_error(Max) :-
    throw(error(resource_error(oro_nesting(Max)), _)).

:- multifile prolog:error_message//1.

prolog:error_message(resource_error(oro_nesting(Max))) -->
    [ 'Brackets or braces nested deeper than ~d levels'-[Max] ].
prolog:error_message(resource_error(oro_parse_limit(Limit))) -->
    [ 'The request took more than its parse budget (~D inferences)'-[Limit] ].

                 /*******************************
                 *           TOKENIZER          *
                 *******************************/

%!  oro_tokenize(+Text, +Delimiter, -Tokens:list(string)) is det.
%
%   Split Text (an atom or a string) on Delimiter (a one-character atom
%   or string, or a character code) the way ORO does: only where the
%   depth of `[ ]` and of `{ }` is zero and neither the double- nor the
%   single-quote flag is on.  The two quote flags toggle independently.
%   A bracket, brace or quote preceded by `\` is not counted; the
%   delimiter itself splits even after a `\`.  Depths may go negative on
%   unbalanced closers, as in ORO.  Empty tokens are kept, so Tokens has
%   at least one element.

oro_tokenize(Text, Delimiter, Tokens) :-
    must_be(text, Text),
    delimiter_code(Delimiter, Code),
    atom_length(Text, Size),
    bounded(Size, tokenize(Text, Code, Tokens)).

delimiter_code(Delimiter, Code) :-
    (   integer(Delimiter)
    ->  must_be(code, Delimiter),
        Code = Delimiter
    ;   must_be(text, Delimiter),
        (   string_length(Delimiter, 1)
        ->  string_code(1, Delimiter, Code)
        ;   domain_error(oro_delimiter, Delimiter)
        )
    ).

tokenize(Text, Delimiter, Tokens) :-
    (   untracked(Text)
    ->  char_code(Sep, Delimiter),
        split_string(Text, Sep, "", Tokens)     % nothing to track
    ;   Delimiter =\= 0,
        \+ sub_atom_icasechk(Text, _, "\u0000")
    ->  scan_tokenize(Text, Delimiter, Tokens)
    ;   general_tokenize(Text, Delimiter, Tokens)
    ).

%   scan_tokenize(+Text, +Delimiter, -Tokens): tokenize/3 stepping only
%   through the characters that can change the tokenizer's state: the
%   tracked ones, found by split_string/4 (Text has no NUL, see
%   one_part/2).  Between two of them lies a segment of plain text,
%   which changes no state and leaves a previous character that is not
%   `\`: where the state is zero, every delimiter in it splits, and one
%   more split_string/4 finds them all.  A set of statements with one
%   quoted label is then a few Prolog steps, not one a statement.

scan_tokenize(Text, Delimiter, Tokens) :-
    char_code(Sep, Delimiter),
    setting(max_nesting, Max),
    string_length(Text, Length),
    scan_chunks(0, Length, Text, Delimiter-Sep, Max, -1, s(0, 0, 0, 0),
                Cuts),
    cut_tokens(Cuts, Text, 0, Tokens).

%   scan_chunks(+Start, +Length, +Text, +Delimiter-Sep, +Max, +Prev,
%   +State, -Cuts): the cuts of Text from offset Start on, read a chunk
%   (chunk_chars/1) at a time.  A segment of plain text may straddle
%   two chunks: its pieces are cut alike, as the state is the same all
%   along it.

scan_chunks(Start, Length, Text, DS, Max, Prev0, State0, Cuts) :-
    (   Start >= Length
    ->  Cuts = []
    ;   chunk_chars(Size),
        Take is min(Size, Length-Start),
        sub_string(Text, Start, Take, _, Chunk),
        split_string(Chunk, "[]{}\"'\\", "", [First|Parts]),
        DS = _-Sep,
        segment(First, Sep, Start, State0, Prev0, Prev1, FirstLength,
                Cuts, Cuts1),
        Pos is Start+FirstLength,
        scan_cuts(Parts, Text, Pos, DS, Max, Prev1-State0, Prev-State,
                  Cuts1, Cuts2),
        Next is Start+Take,
        scan_chunks(Next, Length, Text, DS, Max, Prev, State, Cuts2)
    ).

%   scan_cuts(+Parts, +Text, +Pos, +Delimiter-Sep, +Max, +Prev0-State0,
%   -Prev-State, -Cuts, ?Tail)
%
%   The tracked character at offset Pos of Text is followed by the
%   segment that is the first of Parts.  Cuts (ending in Tail) are the
%   offsets of the delimiters Text splits at, as tokenizer_step/6
%   decides them.  (A delimiter that is itself a tracked character is
%   decided here, and no segment holds one.)  Prev-State is the
%   tokenizer's after the last of Parts.  A depth past Max raises
%   resource_error(oro_nesting(Max)).

scan_cuts([], _, _, _, _, End, End, Tail, Tail).
scan_cuts([Part|Parts], Text, Pos, D-Sep, Max, Prev-State0, End,
          Cuts, Tail) :-
    Index is Pos+1,
    code_at(Index, Text, C),
    tokenizer_step(C, Prev, D, State0, State, Split),
    State = s(SB, CB, _, _),
    (   ( SB > Max ; CB > Max )
    ->  nesting_error(Max)
    ;   true
    ),
    (   Split == true
    ->  Cuts = [Pos|Cuts1]
    ;   Cuts = Cuts1
    ),
    segment(Part, Sep, Index, State, C, Prev1, Length, Cuts1, Cuts2),
    Pos1 is Index+Length,
    scan_cuts(Parts, Text, Pos1, D-Sep, Max, Prev1-State, End, Cuts2, Tail).

%   segment(+Segment, +Sep, +Start, +State, +Prev0, -Prev, -Length,
%   -Cuts, ?Tail): the segment of plain text Segment, of Length, at
%   offset Start, read in State: Cuts (ending in Tail) are its
%   delimiters if State is zero; Prev is the character before what
%   follows it (Prev0 if it is empty, else a plain one).

segment(Segment, Sep, Start, State, Prev0, Prev, Length, Cuts, Tail) :-
    (   State == s(0, 0, 0, 0)
    ->  segment_cuts(Segment, Sep, Start, Cuts, Tail)
    ;   Cuts = Tail
    ),
    string_length(Segment, Length),
    (   Length =:= 0
    ->  Prev = Prev0
    ;   Prev = -1
    ).

%   segment_cuts(+Segment, +Sep, +Start, -Cuts, ?Tail): Cuts, ending in
%   Tail, are the offsets in Text of the delimiters Sep in Segment, a
%   segment at offset Start of Text where the state is zero.

segment_cuts(Segment, Sep, Start, Cuts, Tail) :-
    split_string(Segment, Sep, "", [First|Rest]),
    string_length(First, Length),
    Pos is Start+Length,
    rest_cuts(Rest, Pos, Cuts, Tail).

rest_cuts([], _, Tail, Tail).
rest_cuts([Piece|Pieces], Pos, [Pos|Cuts], Tail) :-
    string_length(Piece, Length),
    Next is Pos+1+Length,
    rest_cuts(Pieces, Next, Cuts, Tail).

%   code_at(+Index, +Text, -Code): string_code/3 in constant time.  In
%   SWI-Prolog 9.0.4, string_code/3 on a string takes time in
%   proportion to its length, wherever Index is: 1.7 us a call on 3,000
%   characters, 0.06 us on 3 (a scratch measurement).  A request's set
%   of statements is such a string.

code_at(Index, Text, Code) :-
    Before is Index-1,
    sub_string(Text, Before, 1, _, Char),
    string_code(1, Char, Code).

cut_tokens([], Text, Start, [Token]) :-
    sub_string(Text, Start, _, 0, Token).
cut_tokens([Cut|Cuts], Text, Start, [Token|Tokens]) :-
    Length is Cut-Start,
    sub_string(Text, Start, Length, _, Token),
    Next is Cut+1,
    cut_tokens(Cuts, Text, Next, Tokens).

%   general_tokenize(+Text, +Delimiter, -Tokens): tokenize/3 code by
%   code, tracking depths and quotes.

general_tokenize(Text, Delimiter, Tokens) :-
    setting(max_nesting, Max),
    string_codes(Text, Codes),
    tokens(Codes, Delimiter-Max, -1, Tokens).

%   untracked(+Text): Text has none of the characters the tokenizer
%   tracks, and no NUL.

untracked(Text) :-
    one_part(Text, "[]{}\"'\\").

%!  plain_text(+Text) is semidet.
%
%   Text has none of the characters the tokenizer, cleanValue or the
%   statement parser treat specially: no quote, bracket, brace or
%   backslash and no control character (codes 0-31).  On such a text
%   tokenizing is splitting, Java's trim() only removes spaces and
%   unescaping changes nothing.  One C-level scan.

plain_text(Text) :-
    plain_specials(Specials),
    one_part(Text, Specials).

%   plain_specials(-Chars): `[]{}"'\` and the codes 1-31, as a string.
%   local_specials(-Chars): those and `:#<^@`.  quote_specials(-Chars):
%   those of plain_specials/1 but the quotes.  (All three computed at
%   compile time.  NUL cannot be in such a set: split_string/4 reads its
%   separators up to the first NUL.)

term_expansion(plain_specials(generated), plain_specials(Specials)) :-
    plain_special_codes(Codes),
    string_codes(Specials, Codes).
term_expansion(quote_specials(generated), quote_specials(Specials)) :-
    plain_special_codes(Codes),
    subtract(Codes, `"'`, Quoteless),
    string_codes(Specials, Quoteless).
term_expansion(local_specials(generated), local_specials(Specials)) :-
    plain_special_codes(Codes),
    append(Codes, `:#<^@`, Local),
    string_codes(Specials, Local).

plain_special_codes([0'[, 0'], 0'{, 0'}, 0'", 0'\', 0'\\|Controls]) :-
    numlist(1, 31, Controls).

plain_specials(generated).
local_specials(generated).
quote_specials(generated).

%   one_part(+Text, +Separators): Text has none of Separators and no
%   NUL.  SWI-Prolog 9.0.4's split_string/4 takes NUL for a separator
%   inside the text and for padding at its ends, so a text with a NUL
%   comes back in several parts or shorter.  Where split_string/4 does
%   not do that, no_nul/1 looks for one.

one_part(Text, Separators) :-
    string_length(Text, Length),
    chunk_chars(Size),
    (   Length =< Size
    ->  split_string(Text, Separators, "", [Part]),
        string_length(Part, Length)
    ;   one_part_chunks(0, Length, Size, Text, Separators)
    ),
    no_nul(Text).

%   one_part_chunks(+Start, +Length, +Size, +Text, +Separators): the
%   chunks of Text from Start on have none of Separators; one chunk at
%   a time, so that a text full of them fails at its first chunk.

one_part_chunks(Start, Length, Size, Text, Separators) :-
    (   Start >= Length
    ->  true
    ;   Take is min(Size, Length-Start),
        sub_string(Text, Start, Take, _, Chunk),
        split_string(Chunk, Separators, "", [Part]),
        string_length(Part, Take),
        Next is Start+Take,
        one_part_chunks(Next, Length, Size, Text, Separators)
    ).

:- if(( split_string("a\u0000b", "", "", [_, _]),
        split_string("\u0000a\u0000", "", "", ["a"])
      )).
no_nul(_).
:- else.
no_nul(Text) :-
    \+ sub_atom_icasechk(Text, _, "\u0000").
:- endif.

tokens(Codes, Delimiter-Max, Prev, [Token|Tokens]) :-
    token(Codes, Delimiter-Max, Prev, s(0, 0, 0, 0), TokenCodes, Rest),
    string_codes(Token, TokenCodes),
    (   Rest == end
    ->  Tokens = []
    ;   tokens(Rest, Delimiter-Max, Delimiter, Tokens)
    ).

%   token(+Codes, +Delimiter-Max, +Prev, +State, -TokenCodes, -Rest)
%
%   Rest is `end` at the end of the text, else the codes after the
%   delimiter that ended the token.  After a split every depth and flag
%   is zero by construction, so the next token starts from zeros.  A
%   depth past Max raises resource_error(oro_nesting(Max)).

token([], _, _, _, [], end).
token([C|Cs], D-Max, Prev, State0, Token, Rest) :-
    tokenizer_step(C, Prev, D, State0, State, Split),
    (   Split == true
    ->  Token = [],
        Rest = Cs
    ;   State = s(SB, CB, _, _),
        ( SB > Max ; CB > Max )
    ->  nesting_error(Max)
    ;   Token = [C|Token1],
        token(Cs, D-Max, C, State, Token1, Rest)
    ).

%   tokenizer_step(+C, +Prev, +Delimiter, +State0, -State, -Split): the
%   tokenizer reads C, Prev being the character before it.  A state is
%   s(Brackets, Braces, InDouble, InSingle); Split is `true` if the
%   text splits at C.

tokenizer_step(C, Prev, D, State0, State, Split) :-
    (   Prev == 0'\\
    ->  State = State0
    ;   State0 = s(SB0, CB0, DQ0, SQ0),
        count(C, SB0, CB0, DQ0, SQ0, SB, CB, DQ, SQ),
        State = s(SB, CB, DQ, SQ)
    ),
    (   C == D,
        State == s(0, 0, 0, 0)
    ->  Split = true
    ;   Split = false
    ).

count(0'[,  SB0, CB,  DQ,  SQ,  SB, CB, DQ, SQ) :- !, SB is SB0+1.
count(0'],  SB0, CB,  DQ,  SQ,  SB, CB, DQ, SQ) :- !, SB is SB0-1.
count(0'{,  SB,  CB0, DQ,  SQ,  SB, CB, DQ, SQ) :- !, CB is CB0+1.
count(0'},  SB,  CB0, DQ,  SQ,  SB, CB, DQ, SQ) :- !, CB is CB0-1.
count(0'",  SB,  CB,  DQ0, SQ,  SB, CB, DQ, SQ) :- !, DQ is 1-DQ0.
count(0'\', SB,  CB,  DQ,  SQ0, SB, CB, DQ, SQ) :- !, SQ is 1-SQ0.
count(_,    SB,  CB,  DQ,  SQ,  SB, CB, DQ, SQ).


                 /*******************************
                 *          CLEAN VALUE         *
                 *******************************/

%!  oro_clean_value(+Text, -String) is det.
%
%   ORO's `cleanValue`: trim leading and trailing characters up to
%   U+0020 (Java `trim()`), remove one outer pair of matching `"` or
%   `'`, then Java-unescape: `\\ \' \" \r \f \t \n \b \uXXXX`; any other
%   `\x` gives `x`, a lone trailing `\` is kept.  A `\uXXXX` pair
%   encoding a UTF-16 surrogate pair gives one character.
%
%   @error syntax_error(oro_unicode_escape(Text)) if a `\u` is not
%          followed by four hexadecimal digits, or stands for half of
%          a surrogate pair without the other half.

oro_clean_value(Text, String) :-
    must_be(text, Text),
    atom_length(Text, Size),
    bounded(Size, clean_value(Text, String)).

clean_value(Text, String) :-
    (   plain_text(Text)                    % only spaces to trim
    ->  split_string(Text, "", " ", [String])
    ;   general_clean_value(Text, String)
    ).

%   general_clean_value(+Text, -String): clean_value/2 the general way.

general_clean_value(Text, String) :-
    trim(Text, Trimmed),
    (   quoted(Trimmed, _)
    ->  sub_string(Trimmed, 1, _, 1, Inner)
    ;   Inner = Trimmed
    ),
    unescape(Inner, Text, String).

%   trim(+Text, -String): Java String.trim(), without building a code
%   list: only the whitespace at both ends is looked at, each character
%   in constant time (code_at/3).

trim(Text, Trimmed) :-
    string_length(Text, Len),
    skip_forward(Text, 1, Len, Start),
    skip_backward(Text, Len, Start, End),
    Before is Start-1,
    Length is End-Start+1,
    sub_string(Text, Before, Length, _, Trimmed).

skip_forward(Text, I, Len, Start) :-
    (   I =< Len,
        code_at(I, Text, C),
        C =< 0'\s
    ->  I1 is I+1,
        skip_forward(Text, I1, Len, Start)
    ;   Start = I
    ).

skip_backward(Text, I, Start, End) :-
    (   I >= Start,
        code_at(I, Text, C),
        C =< 0'\s
    ->  I1 is I-1,
        skip_backward(Text, I1, Start, End)
    ;   End = I
    ).

%   quoted(+Text, -Quote): Text is at least two characters long and
%   starts and ends with the same quote character.

quoted(Text, Q) :-
    string_length(Text, Len),
    Len >= 2,
    string_code(1, Text, Q),
    quote_code(Q),
    string_code(Len, Text, Q).

quote_code(0'").
quote_code(0'\').

%   unescape(+Text, +Original, -String): Original is the text quoted in
%   the error term.

unescape(Text, Original, String) :-
    (   sub_string(Text, _, _, _, "\\")
    ->  string_codes(Text, Codes),
        unescape_codes(Codes, Original, Unescaped),
        string_codes(String, Unescaped)
    ;   String = Text
    ).

unescape_codes([], _, []).
unescape_codes([C|Cs], Original, Out) :-
    (   C == 0'\\
    ->  escape(Cs, Original, Out)
    ;   Out = [C|Out1],
        unescape_codes(Cs, Original, Out1)
    ).

escape([], _, [0'\\]).
escape([C|Cs], Original, Out) :-
    (   C == 0'u
    ->  unicode_escape(Cs, Original, Out)
    ;   escape_char(C, E)
    ->  Out = [E|Out1],
        unescape_codes(Cs, Original, Out1)
    ;   Out = [C|Out1],
        unescape_codes(Cs, Original, Out1)
    ).

escape_char(0'r, 0'\r).
escape_char(0'f, 0'\f).
escape_char(0't, 0'\t).
escape_char(0'n, 0'\n).
escape_char(0'b, 0'\b).

unicode_escape(Cs, Original, [Code|Out]) :-
    (   hex4(Cs, Unit, Rest)
    ->  true
    ;   string_from_text(Original, Text),
        throw(error(syntax_error(oro_unicode_escape(Text)), _))
    ),
    (   Unit >= 0xD800,
        Unit =< 0xDBFF,
        Rest = [0'\\, 0'u|Rest1],
        hex4(Rest1, Low, Rest2),
        Low >= 0xDC00,
        Low =< 0xDFFF
    ->  Code is 0x10000 + ((Unit-0xD800) << 10) + (Low-0xDC00),
        unescape_codes(Rest2, Original, Out)
    ;   Unit >= 0xD800,
        Unit =< 0xDFFF                      % half a pair: no character
    ->  string_from_text(Original, Text),
        throw(error(syntax_error(oro_unicode_escape(Text)), _))
    ;   Code = Unit,
        unescape_codes(Rest, Original, Out)
    ).

hex4([A,B,C,D|Rest], Value, Rest) :-
    code_type(A, xdigit(VA)),
    code_type(B, xdigit(VB)),
    code_type(C, xdigit(VC)),
    code_type(D, xdigit(VD)),
    Value is VA<<12 + VB<<8 + VC<<4 + VD.

string_from_text(Text, String) :-
    (   string(Text)
    ->  String = Text
    ;   atom_string(Text, String)
    ).


                 /*******************************
                 *       SETS, LISTS, MAPS      *
                 *******************************/

%!  oro_parse_collection(+Kind, +Text, -Elements:list(string)) is det.
%
%   Decode a `Set<String>` (Kind `set`) or `List<String>` (Kind `list`)
%   parameter.  The empty text and `null` (any case) give `[]`.
%   Otherwise Text must start with `[` and end with `]` (it is not
%   trimmed); the inside is split on `,` by oro_tokenize/3 and each
%   element goes through oro_clean_value/2.  `[]` gives `[]`, `[ ]`
%   gives `[""]`.  A set drops duplicates, keeping the first occurrence
%   of each element; a list keeps order and duplicates.
%
%   @error domain_error(oneof([set, list]), Kind) for another Kind.
%   @error type_error(oro_collection, Text) if Text is not framed by
%          `[ ]`.
%   @error syntax_error(oro_unicode_escape(Element)) from
%          oro_clean_value/2.

oro_parse_collection(Kind, Text, Elements) :-
    must_be(atom, Kind),
    (   collection_kind(Kind)
    ->  true
    ;   domain_error(oneof([set, list]), Kind)
    ),
    must_be(text, Text),
    atom_length(Text, Size),
    bounded(Size, collection(Kind, Text, Elements)).

collection(Kind, Text, Elements) :-
    collection_elements(Text, Elements0),
    (   Kind == set
    ->  set_elements(Elements0, Elements)
    ;   Elements = Elements0
    ).

%   set_elements(+List, -Set): List less its duplicates, the first
%   occurrence of each kept.  A batch rarely has any: one sort tells.

set_elements(List, Set) :-
    sort(List, Sorted),
    (   same_length(List, Sorted)
    ->  Set = List
    ;   list_to_set(List, Set)
    ).

collection_kind(set).
collection_kind(list).

collection_elements(Text, Elements) :-
    (   null_text(Text)
    ->  Elements = []
    ;   framed(Text, 0'[, 0'], Inner)
    ->  (   Inner == ""
        ->  Elements = []
        ;   quoted_elements(Inner, Elements0)
        ->  Elements = Elements0
        ;   plain_text(Inner)               % split, trim: one C call
        ->  split_string(Inner, ",", " ", Elements)
        ;   one_quote_elements(Inner, Elements0)
        ->  Elements = Elements0
        ;   general_elements(Inner, Elements)
        )
    ;   throw(error(type_error(oro_collection, Text), _))
    ).

%   quoted_elements(+Inner, -Elements): the fast path for the inside of
%   a collection whose elements are all quoted with the same quote, as
%   the clients send them: liboro `"a b c","d \"e\" f"`, pyoro `'a b
%   c', 'd e "f"'`.  It applies when the elements hold no bracket or
%   brace, no backslash but one escaping the quote, and the other quote
%   an even number of times, and are separated by one comma with spaces
%   around it at most.  The general path then splits exactly at those
%   commas (the quote's flag is on inside each element, the other
%   quote's flag is off again at its end), trims what is around the
%   quotes and takes them off, and its unescaping turns each escaped
%   quote into the quote: each element is what lies between its quotes,
%   escapes undone (a control character inside is kept either way).
%   Fails on anything else.

quoted_elements(Inner, Elements) :-
    opening_quote(Inner, Code),
    quote_pair(Code, Quote, Other),
    one_part(Inner, "[]{}"),
    (   sub_atom_icasechk(Inner, _, "\\")
    ->  split_string(Inner, "\\", "", [_|Escaped]),
        maplist(escaped_quote(Quote), Escaped),
        Escapes = true
    ;   Escapes = false
    ),
    (   sub_atom_icasechk(Inner, _, Other)
    ->  Others = true
    ;   Others = false
    ),
    split_string(Inner, Quote, "", [Before|Parts]),
    split_string(Before, "", " ", [""]),
    quoted_parts(Parts, q(Quote, Escapes, Other, Others), Elements).

%   one_quote_elements(+Inner, -Elements): the fast path for the inside
%   of a collection whose only special characters are quotes of one
%   kind, none of which opens an element, with no comma between a quote
%   and the next: a set of statements sent unquoted, one of them with a
%   label, `a rdf:type Cup, a rdfs:label "cup 1", b isOn a`.  (No
%   bracket, brace, backslash or control character: see
%   quote_specials/1.)  The tokenizer's only state is then the quote's
%   flag, which is off at every comma, so the text splits at each one;
%   and as no element starts with a quote nor has an escape,
%   cleanValue only trims the spaces around it.  A text that starts a
%   quoted run and never ends it has an odd number of parts between
%   quotes, and fails.  Fails on anything else.

one_quote_elements(Inner, Elements) :-
    quote_specials(Specials),
    one_part(Inner, Specials),
    (   \+ sub_atom_icasechk(Inner, _, "'")
    ->  Quote = "\""
    ;   \+ sub_atom_icasechk(Inner, _, "\"")
    ->  Quote = "'"
    ),
    split_string(Inner, Quote, "", [Before|Runs]),
    \+ opens_first(Before),
    quoted_runs(Runs),
    split_string(Inner, ",", " ", Elements).

%   opens_first(+Before): the quote after Before, the text before the
%   first quote, starts an element.  opens_next(+Between): so does the
%   quote after Between, the text between a quoted run and the next.

opens_first(Before) :-
    split_string(Before, "", " ", [Trimmed]),
    (   Trimmed == ""
    ->  true
    ;   sub_string(Trimmed, _, 1, 0, ",")
    ).

opens_next(Between) :-
    split_string(Between, "", " ", [Trimmed]),
    sub_string(Trimmed, _, 1, 0, ",").

%   quoted_runs(+Runs): Runs are the inside of a quoted run, what comes
%   after it, and so on; no inside has a comma, no quote but the first
%   opens an element.

quoted_runs([Inside, After|Runs]) :-
    \+ sub_atom_icasechk(Inside, _, ","),
    (   Runs == []
    ->  true
    ;   \+ opens_next(After),
        quoted_runs(Runs)
    ).

%   opening_quote(+Inner, -Code): the first character of Inner that is
%   not a space (the clients write none).

opening_quote(Inner, Code) :-
    code_at(1, Inner, Code0),
    (   Code0 == 0'\s
    ->  split_string(Inner, "", " ", [Trimmed]),
        code_at(1, Trimmed, Code)
    ;   Code = Code0
    ).

quote_pair(0'", "\"", "'").
quote_pair(0'\', "'", "\"").

escaped_quote(Quote, Text) :-
    sub_string(Text, 0, 1, _, Quote).

%   quoted_parts(+Parts, +Q, -Elements): Parts, the pieces of the text
%   between quotes, are an element, what separates it from the next,
%   and so on.  An element is several pieces where a piece ends with
%   the backslash escaping the quote after it.  Q holds the quote,
%   whether the text has escapes, the other quote and whether the text
%   has it.

quoted_parts(Parts0, Q, [Element|Elements]) :-
    quoted_element(Parts0, Q, Element, [Between|Parts]),
    (   arg(4, Q, true)
    ->  arg(3, Q, Other),
        split_string(Element, Other, "", OtherParts),
        length(OtherParts, N),
        N mod 2 =:= 1                       % the other quote: even times
    ;   true
    ),
    (   Parts == []
    ->  split_string(Between, "", " ", [""]),
        Elements = []
    ;   comma(Between),
        quoted_parts(Parts, Q, Elements)
    ).

quoted_element(Parts0, Q, Element, Parts) :-
    element_pieces(Parts0, Q, Pieces, Parts),
    (   Pieces = [Element]
    ->  true
    ;   arg(1, Q, Quote),
        Pieces = [First|Rest],
        foldl(quote_before(Quote), Rest, Joined, []),
        atomics_to_string([First|Joined], Element)  % once: linear
    ).

quote_before(Quote, Piece, [Quote, Piece|Tail], Tail).

%   element_pieces(+Parts0, +Q, -Pieces, -Parts): Pieces are the
%   pieces of one element, each backslash escaping a quote taken off;
%   the element is Pieces joined by the quote.

element_pieces([Piece|Parts0], Q, Pieces, Parts) :-
    (   arg(2, Q, true),
        sub_string(Piece, Length, 1, 0, "\\")
    ->  sub_string(Piece, 0, Length, _, Head),
        Pieces = [Head|Pieces1],
        element_pieces(Parts0, Q, Pieces1, Parts)
    ;   Pieces = [Piece],
        Parts = Parts0
    ).

comma(Between) :-
    (   Between == ","
    ->  true
    ;   Between == ", "
    ->  true
    ;   split_string(Between, "", " ", [","])
    ).

%   general_elements(+Inner, -Elements): the elements of the non-empty
%   inside of a collection, the general way.

general_elements(Inner, Elements) :-
    tokenize(Inner, 0',, Tokens),
    maplist(clean_value, Tokens, Elements).

null_text(Text) :-
    string_length(Text, Len),
    (   Len =:= 0
    ->  true
    ;   Len =:= 4,
        string_lower(Text, "null")
    ).

%   framed(+Text, +Open, +Close, -Inner)

framed(Text, Open, Close, Inner) :-
    string_length(Text, Len),
    Len >= 2,
    code_at(1, Text, Open),
    code_at(Len, Text, Close),
    sub_string(Text, 1, _, 1, Inner).

%!  oro_parse_map(+Text, -Pairs:list(pair(string,string))) is det.
%
%   Decode a `Map<String,String>` parameter `{k1:v1, k2:v2}` into
%   `Key-Value` pairs of strings, in the order written.  Braces are
%   required; `{}` gives `[]`.  Entries are split on `,` by
%   oro_tokenize/3; each must contain `:` and is split at its first `:`
%   (quotes are not honoured for the colon); key and value go through
%   oro_clean_value/2.
%
%   @error type_error(oro_map, Text) if Text is not framed by `{ }` or an
%          entry has no `:`.

oro_parse_map(Text, Pairs) :-
    must_be(text, Text),
    atom_length(Text, Size),
    bounded(Size, map_pairs(Text, Pairs)).

map_pairs(Text, Pairs) :-
    (   framed(Text, 0'{, 0'}, Inner)
    ->  (   Inner == ""
        ->  Pairs = []
        ;   tokenize(Inner, 0',, Tokens),
            maplist(map_entry(Text), Tokens, Pairs)
        )
    ;   throw(error(type_error(oro_map, Text), _))
    ).

map_entry(Text, Token, Key-Value) :-
    (   sub_string(Token, Before, 1, After, ":")
    ->  sub_string(Token, 0, Before, _, KeyText),
        sub_string(Token, _, After, 0, ValueText),
        clean_value(KeyText, Key),
        clean_value(ValueText, Value)
    ;   throw(error(type_error(oro_map, Text), _))
    ).


                 /*******************************
                 *          STATEMENTS          *
                 *******************************/

%!  oro_parse_statement(+Text, -Triple) is det.
%
%   Parse a complete or partial statement `subject predicate object`
%   into `rdf(S, P, O)`.  Text is trimmed and split on single spaces by
%   oro_tokenize/3.  A token `?name` gives `var(name)` in any position;
%   other subjects and predicates are names expanded by oro_name_iri/2;
%   other objects follow ORO's literal rules (see the module doc) and
%   give an rdf_db literal term or an IRI.
%
%   @error syntax_error(oro_statement_tokens(N, Stmt)) unless there are
%          exactly three tokens; Stmt is the trimmed text (a string).
%   @error syntax_error(oro_statement_empty_token(Stmt)) if one of the
%          three tokens is empty.
%   @error syntax_error(oro_statement_variable(Stmt)) for a bare `?`.
%   @error type_error(oro_statement, Stmt) if a token leaves a quote
%          open (`a b "c d`: a `"` or `'` not closed by one of the same
%          kind, an escaped one not counting), or if an object opens
%          with a quote but is neither a string, a language-tagged nor
%          a typed literal (`"abc"def`).
%   @error syntax_error(oro_invalid_datatype(Type)) for `lex^^type`
%          with an unknown XSD datatype.
%   @error syntax_error(oro_lexical_form(Lex, Type)) for `lex^^type`
%          whose lexical form is not valid for the datatype.

oro_parse_statement(Text, Triple) :-
    must_be(text, Text),
    atom_length(Text, Size),
    bounded(Size, parse_statement(Text, Triple)).

%!  oro_parse_statements(+Texts, -Triples) is det.
%
%   Parse a list of statement texts with oro_parse_statement/2.  The
%   first statement in error raises its error.

oro_parse_statements(Texts, Triples) :-
    must_be(list(text), Texts),
    texts_size(Texts, Size),
    bounded(Size, maplist(parse_statement, Texts, Triples)).

%!  oro_is_partial(+Triple) is semidet.
%
%   True if at least one position of Triple (`rdf(S, P, O)` as made by
%   oro_parse_statement/2) is a variable `var(Name)`.
%
%   @error type_error(oro_triple, Triple) if Triple is not `rdf/3`.

oro_is_partial(Triple) :-
    (   compound(Triple),
        compound_name_arity(Triple, rdf, 3)
    ->  true
    ;   type_error(oro_triple, Triple)
    ),
    Triple = rdf(S, P, O),
    (   is_var_term(S)
    ->  true
    ;   is_var_term(P)
    ->  true
    ;   is_var_term(O)
    ).

is_var_term(Term) :-
    subsumes_term(var(_), Term).

%   parse_statement(+Text, -Triple).  Three fast paths before the
%   general one:
%
%     - local_statement/2: a plain text (see plain_text/1) without any
%       of `:#<^@`, made of three non-empty tokens separated by single
%       spaces with no space around.  Its subject and predicate are
%       names of the default namespace or variables, and so is its
%       object unless it does not start with a letter or is a boolean.
%       Two splits find all that.
%     - plain_statement_tokens/4: a plain text of three non-empty tokens
%       separated by single spaces, with no space around: the text is
%       the statement already trimmed and tokenized.
%     - literal_statement/2: two such tokens, then a literal in
%       double quotes that ends the text (`obj1 rdfs:label "table 2"`),
%       with no quote, backslash, bracket, brace or control character
%       inside: the tokenizer would not split it, and it needs no
%       unescaping.
%
%   Anything else (two spaces, a tab, quotes...) goes through
%   general_statement/2, which also raises the errors.

parse_statement(Text, Triple) :-
    (   local_statement(Text, Triple0)
    ->  Triple = Triple0
    ;   plain_statement_tokens(Text, ST, PT, OT)
    ->  tokens_triple(ST, PT, OT, Text, Triple)
    ;   literal_statement(Text, Triple0)
    ->  Triple = Triple0
    ;   general_statement(Text, Triple)
    ).

local_statement(Text, rdf(S, P, O)) :-
    local_specials(Specials),
    one_part(Text, Specials),
    split_string(Text, " ", "", [ST, PT, OT]),
    ST \== "",
    PT \== "",
    OT \== "",
    local_token(ST, Text, S),
    local_token(PT, Text, P),
    local_object_token(OT, Text, O).

plain_statement_tokens(Text, ST, PT, OT) :-
    plain_text(Text),
    split_string(Text, " ", "", [ST, PT, OT]),
    ST \== "",
    PT \== "",
    OT \== "".

literal_statement(Text, rdf(S, P, O)) :-
    sub_string(Text, _, 1, 0, "\""),       % not a typed or tagged one
    split_string(Text, "\"", "", [Head, Inner, ""]),
    split_string(Head, " ", "", [ST, PT, ""]),
    ST \== "",
    PT \== "",
    plain_text(Head),
    quote_specials(Specials),
    one_part(Inner, Specials),
    resource_token(ST, Text, S),
    resource_token(PT, Text, P),
    string_literal(Inner, O).

%!  general_statement(+Text, -Triple) is det.
%
%   Parse a statement the general way: trim, tokenize, then decide
%   every token.  parse_statement/2 gives the same result faster on the
%   texts its fast paths accept (the tests compare both).

general_statement(Text, Triple) :-
    statement_tokens(Text, Stmt, ST, PT, OT),
    tokens_triple(ST, PT, OT, Stmt, Triple).

tokens_triple(ST, PT, OT, Stmt, rdf(S, P, O)) :-
    resource_token(ST, Stmt, S),
    resource_token(PT, Stmt, P),
    object_token(OT, Stmt, O),
    bracket_free_name(ST, S),
    bracket_free_name(PT, P),
    bracket_free_name(OT, O).

%   bracket_free_name(+Token, +Term): unless Term is a name written
%   without `<...>`, Token has no bracket nor brace: `[x]` or `{x}` is
%   the leftover of a collection, not a name to store.

bracket_free_name(Token, Term) :-
    (   atom(Term),
        \+ string_code(1, Token, 0'<),
        \+ split_string(Token, "[]{}", "", [_])
    ->  string_from_text(Token, String),
        throw(error(syntax_error(oro_statement_name(String)), _))
    ;   true
    ).

%   local_token(+Token, +Stmt, -Term) and local_object_token(+Token,
%   +Stmt, -Term): as resource_token/3 and object_token/3 for a plain
%   token without `:#<^@`: a name needs no further check.

local_token(Token, Stmt, Term) :-
    (   string_code(1, Token, 0'?)
    ->  variable_token(Token, Stmt, Term)
    ;   oro_default_namespace(NS),
        atom_concat(NS, Token, Term)
    ).

local_object_token(Token, Stmt, Term) :-
    string_code(1, Token, C),
    (   C == 0'?
    ->  variable_token(Token, Stmt, Term)
    ;   name_start(C),
        Token \== "true",
        Token \== "false"
    ->  oro_default_namespace(NS),
        atom_concat(NS, Token, Term)
    ;   string_codes(Token, Codes),
        object_codes(Codes, Token, Term)
    ).

statement_tokens(Text, Stmt, ST, PT, OT) :-
    trim(Text, Stmt),
    tokenize(Stmt, 0'\s, Tokens),
    (   Tokens = [ST, PT, OT]
    ->  true
    ;   length(Tokens, N),
        throw(error(syntax_error(oro_statement_tokens(N, Stmt)), _))
    ),
    (   ( ST == "" ; PT == "" ; OT == "" )
    ->  throw(error(syntax_error(oro_statement_empty_token(Stmt)), _))
    ;   true
    ),
    (   member(Token, [ST, PT, OT]),
        \+ quotes_closed(Token)
    ->  quote_error(Stmt)
    ;   true
    ).

%   quotes_closed(+Token): every quote Token opens is closed in it.  A
%   `"` or `'` opens a quoted run, which ends at the next quote of the
%   same kind (the other kind is plain text inside it); a `\` escapes
%   the next character, inside a run or not, as in unescape_codes/3.
%   So `"it's"`, `'say "hi"'` and `a\"b` are closed; `"abc`, `x"`,
%   `john's` and `"a\"` are not.  Only the last token of a statement
%   can fail this: the tokenizer does not split inside quotes.

quotes_closed(Token) :-
    (   split_string(Token, "\"'", "", [_])
    ->  true                                % no quote at all
    ;   string_codes(Token, Codes),
        closed_codes(Codes)
    ).

closed_codes([]).
closed_codes([C|Cs]) :-
    (   C == 0'\\
    ->  (   Cs = [_|Cs1]
        ->  closed_codes(Cs1)
        ;   true
        )
    ;   quote_code(C)
    ->  quoted_run(Cs, C, Rest),
        closed_codes(Rest)
    ;   closed_codes(Cs)
    ).

%   quoted_run(+Codes, +Quote, -Rest): Codes starts inside a run opened
%   by Quote; Rest follows the quote that closes it.  Fails if none does.

quoted_run([C|Cs], Q, Rest) :-
    (   C == Q
    ->  Rest = Cs
    ;   C == 0'\\
    ->  Cs = [_|Cs1],
        quoted_run(Cs1, Q, Rest)
    ;   quoted_run(Cs, Q, Rest)
    ).

%   quote_error(+Stmt): Stmt has a token with an unterminated quote, or
%   an object token opening with a quote that is not a literal.  The
%   error is the one server/oro_errors.pl maps to ORO's
%   IllegalStatementException for a text that is not a statement.

quote_error(Stmt) :-
    string_from_text(Stmt, String),
    throw(error(type_error(oro_statement, String), _)).

%   resource_token(+Token, +Stmt, -Term) and object_token(+Token, +Stmt,
%   -Term): Token is not empty; Stmt is the statement (for errors).
%
%   An object token that starts with a letter, is not a boolean and
%   has no `^` nor `@` can only be a name (so neither a typed nor a
%   language-tagged literal): the common case, on the hot path of every
%   add.  Other tokens are decided by object_codes/3, which gives names
%   too.

resource_token(Token, Stmt, Term) :-
    (   string_code(1, Token, 0'?)
    ->  variable_token(Token, Stmt, Term)
    ;   oro_name_iri(Token, Term)
    ).

variable_token(Token, Stmt, var(Name)) :-
    sub_atom(Token, 1, _, 0, Name),
    (   Name == ''
    ->  string_from_text(Stmt, StmtString),
        throw(error(syntax_error(oro_statement_variable(StmtString)), _))
    ;   true
    ).

object_token(Token, Stmt, Term) :-
    string_code(1, Token, C),
    (   C == 0'?
    ->  variable_token(Token, Stmt, Term)
    ;   name_start(C),
        Token \== "true",
        Token \== "false"
    ->  (   split_string(Token, ":#<^@", "", [_])
        ->  oro_default_namespace(NS),
            atom_concat(NS, Token, Term)
        ;   split_string(Token, "^@", "", [_])
        ->  oro_name_iri(Token, Term)
        ;   string_codes(Token, Codes),
            object_codes(Codes, Token, Term)
        )
    ;   string_codes(Token, Codes),
        object_codes(Codes, Token, Term0),
        (   atom(Term0),
            quote_code(C)
        ->  quote_error(Stmt)               % "abc"def, "x"@, 'a'b
        ;   Term = Term0
        )
    ).

%   name_start(+Code): Code may start a name: a letter (code_type/2
%   `alpha` less digits and `_`), decided by arithmetic for ASCII.

name_start(C) :-
    (   C < 128
    ->  (   C >= 0'a
        ->  C =< 0'z
        ;   C >= 0'A,
            C =< 0'Z
        )
    ;   code_type(C, alpha),
        \+ code_type(C, digit)
    ).

%   object_codes(+Codes, +Token, -Term): ORO's parseLiteral, in order:
%   typed literal, boolean, quoted string, language-tagged string,
%   integer, double, resource.

object_codes(Codes, Token, Term) :-
    (   typed_split(Codes, LexCodes, TypeCodes)
    ->  typed_literal(LexCodes, TypeCodes, Term)
    ;   Token == "true"
    ->  rdf_equal(Type, xsd:boolean),
        Term = literal(type(Type, true))
    ;   Token == "false"
    ->  rdf_equal(Type, xsd:boolean),
        Term = literal(type(Type, false))
    ;   quoted(Token, _)
    ->  sub_string(Token, 1, _, 1, Inner),
        unescape(Inner, Token, LexString),
        string_literal(LexString, Term)
    ;   lang_split(Codes, LexCodes, Lang)
    ->  unescape_codes(LexCodes, Token, Unescaped),
        atom_codes(Lex, Unescaped),
        Term = literal(lang(Lang, Lex))
    ;   integer_lexical(Codes)
    ->  atom_codes(Lex, Codes),
        rdf_equal(Type, xsd:int),
        Term = literal(type(Type, Lex))
    ;   decimal_lexical(Codes, true)
    ->  atom_codes(Lex, Codes),
        rdf_equal(Type, xsd:double),
        Term = literal(type(Type, Lex))
    ;   oro_name_iri(Token, Term)
    ).

%   string_literal(+LexString, -Term): the xsd:string literal of
%   LexString (unescaped), as a quoted object token gives it.

string_literal(LexString, literal(type(Type, Lex))) :-
    atom_string(Lex, LexString),
    rdf_equal(Type, xsd:string).

%   typed_split(+Codes, -Lex, -Type): split at the last `^^` that has
%   no quote after it, i.e. the last `^^` outside the quoted lexical
%   form.  Types never contain quotes; deciding from the right keeps an
%   apostrophe inside `"it's"^^xsd:string` from hiding the separator.

typed_split(Codes, Lex, Type) :-
    memberchk(0'^, Codes),
    last_separator(Codes, 0, none, Pos),
    integer(Pos),
    length(Lex, Pos),
    append(Lex, [0'^, 0'^|Type], Codes).

last_separator([], _, Pos, Pos).
last_separator([C|Cs], I, Pos0, Pos) :-
    (   C == 0'^,
        Cs = [0'^|_]
    ->  Pos1 = I
    ;   quote_code(C)
    ->  Pos1 = none
    ;   Pos1 = Pos0
    ),
    I1 is I+1,
    last_separator(Cs, I1, Pos1, Pos).

typed_literal(LexCodes0, TypeCodes0, literal(type(Type, Lex))) :-
    string_codes(LexText, LexCodes0),
    string_codes(TypeText, TypeCodes0),
    (   quoted(LexText, _)
    ->  sub_string(LexText, 1, _, 1, Inner),
        unescape(Inner, LexText, LexString)
    ;   LexString = LexText
    ),
    (   framed(TypeText, 0'<, 0'>, TypeName)
    ->  true
    ;   TypeName = TypeText
    ),
    (   TypeName == ""
    ->  throw(error(syntax_error(oro_invalid_datatype(TypeText)), _))
    ;   true
    ),
    oro_name_iri(TypeName, Type),
    check_datatype(Type, LexString, TypeText),
    atom_string(Lex, LexString).

check_datatype(Type, LexString, TypeText) :-
    lexical_verdict(Type, LexString, Verdict),
    datatype_verdict(Verdict, LexString, TypeText).

%   lexical_verdict(+Type, +LexText, -Verdict): whether LexText is a
%   lexical form of the datatype Type: `ok` (or a datatype out of the
%   XSD namespace, not checked), `bad_form`, or `bad_datatype` (an XSD
%   name that is no datatype).  datatype_verdict(+Verdict, +LexText,
%   +TypeText) raises the syntax error of a bad one, naming the type as
%   the statement did.

lexical_verdict(Type, LexText, Verdict) :-
    oro_prefix(xsd, NS),
    (   atom_concat(NS, Local, Type)
    ->  (   xsd_lexical(Local, Check)
        ->  string_codes(LexText, Codes),
            (   lexical_ok(Check, Codes)
            ->  Verdict = ok
            ;   Verdict = bad_form
            )
        ;   Verdict = bad_datatype
        )
    ;   Verdict = ok
    ).

datatype_verdict(ok, _, _).
datatype_verdict(bad_form, LexText, TypeText) :-
    throw(error(syntax_error(oro_lexical_form(LexText, TypeText)), _)).
datatype_verdict(bad_datatype, _, TypeText) :-
    throw(error(syntax_error(oro_invalid_datatype(TypeText)), _)).

%   lang_split(+Codes, -LexCodes, -Lang): Codes is `"lex"@lang` or
%   `'lex'@lang`.  LexCodes is the text between the quotes.

lang_split([Q|Codes], Lex, Lang) :-
    quote_code(Q),
    memberchk(0'@, Codes),
    reverse(Codes, Reversed),
    append(RevTag, [0'@, Q|RevLex], Reversed),
    !,
    RevTag \== [],
    reverse(RevTag, TagCodes),
    lang_tag(TagCodes),
    reverse(RevLex, Lex),
    atom_codes(Lang, TagCodes).

lang_tag(Codes) :-
    phrase(lang_tag, Codes).

lang_tag -->
    alphas(1),
    lang_subtags.

lang_subtags --> [].
lang_subtags -->
    "-",
    alnums(1),
    lang_subtags.

alphas(N) -->
    [C],
    { code_type(C, alpha), C < 128, C \== 0'_ },
    !,
    { N1 is N-1 },
    alphas(N1).
alphas(N) -->
    { N =< 0 }.

alnums(N) -->
    [C],
    { code_type(C, alnum), C < 128 },
    !,
    { N1 is N-1 },
    alnums(N1).
alnums(N) -->
    { N =< 0 }.


                 /*******************************
                 *       LEXICAL FORMS          *
                 *******************************/

%   xsd_lexical(?Local, ?Check): the XSD datatypes oro accepts in
%   `lex^^xsd:Local` and how their lexical forms are checked.

xsd_lexical(string,             any).
xsd_lexical(normalizedString,   any).
xsd_lexical(token,              any).
xsd_lexical(language,           any).
xsd_lexical('NMTOKEN',          any).
xsd_lexical('NMTOKENS',         any).
xsd_lexical('Name',             any).
xsd_lexical('NCName',           any).
xsd_lexical('ID',               any).
xsd_lexical('IDREF',            any).
xsd_lexical('IDREFS',           any).
xsd_lexical('ENTITY',           any).
xsd_lexical('ENTITIES',         any).
xsd_lexical('QName',            any).
xsd_lexical('NOTATION',         any).
xsd_lexical(anyURI,             any).
xsd_lexical(base64Binary,       base64).
xsd_lexical(hexBinary,          hex).
xsd_lexical(boolean,            boolean).
xsd_lexical(decimal,            decimal).
xsd_lexical(double,             double).
xsd_lexical(float,              double).
xsd_lexical(integer,            integer(inf, inf)).
xsd_lexical(nonPositiveInteger, integer(inf, 0)).
xsd_lexical(negativeInteger,    integer(inf, -1)).
xsd_lexical(nonNegativeInteger, integer(0, inf)).
xsd_lexical(positiveInteger,    integer(1, inf)).
xsd_lexical(long,               integer(-9223372036854775808, 9223372036854775807)).
xsd_lexical(int,                integer(-2147483648, 2147483647)).
xsd_lexical(short,              integer(-32768, 32767)).
xsd_lexical(byte,               integer(-128, 127)).
xsd_lexical(unsignedLong,       integer(0, 18446744073709551615)).
xsd_lexical(unsignedInt,        integer(0, 4294967295)).
xsd_lexical(unsignedShort,      integer(0, 65535)).
xsd_lexical(unsignedByte,       integer(0, 255)).
xsd_lexical(dateTime,           grammar(date_time(optional))).
xsd_lexical(dateTimeStamp,      grammar(date_time(required))).
xsd_lexical(date,               grammar(date)).
xsd_lexical(time,               grammar(time)).
xsd_lexical(gYear,              grammar(g_year)).
xsd_lexical(gYearMonth,         grammar(g_year_month)).
xsd_lexical(gMonth,             grammar(g_month)).
xsd_lexical(gMonthDay,          grammar(g_month_day)).
xsd_lexical(gDay,               grammar(g_day)).
xsd_lexical(duration,           grammar(duration)).
xsd_lexical(dayTimeDuration,    grammar(duration)).
xsd_lexical(yearMonthDuration,  grammar(duration)).

lexical_ok(any, _).
lexical_ok(boolean, Codes) :-
    memberchk(Codes, [`true`, `false`, `1`, `0`]).
lexical_ok(decimal, Codes) :-
    (   decimal_lexical(Codes, false)
    ->  true
    ;   integer_lexical(Codes)              % "1"^^xsd:decimal
    ).
lexical_ok(double, Codes) :-
    (   memberchk(Codes, [`INF`, `+INF`, `-INF`, `NaN`])
    ->  true
    ;   decimal_lexical(Codes, true)
    ;   integer_lexical(Codes)
    ).
lexical_ok(integer(Min, Max), Codes) :-
    integer_lexical(Codes),
    (   Codes = [0'+|Digits]
    ->  number_codes(Value, Digits)
    ;   number_codes(Value, Codes)
    ),
    (   Min == inf
    ->  true
    ;   Value >= Min
    ),
    (   Max == inf
    ->  true
    ;   Value =< Max
    ).
lexical_ok(hex, Codes) :-
    length(Codes, Len),
    Len mod 2 =:= 0,
    forall(member(C, Codes), code_type(C, xdigit(_))).
lexical_ok(base64, Codes) :-
    forall(member(C, Codes), base64_code(C)).
lexical_ok(grammar(Grammar), Codes) :-
    phrase(Grammar, Codes),
    !.

base64_code(C) :-
    (   code_type(C, alnum),
        C < 128
    ->  true
    ;   memberchk(C, `+/= `)
    ).

%   integer_lexical(+Codes): `[+-]?[0-9]+`

integer_lexical(Codes) :-
    (   Codes = [S|Digits],
        sign_code(S)
    ->  true
    ;   Digits = Codes
    ),
    digits1(Digits, []).

sign_code(0'+).
sign_code(0'-).

%   decimal_lexical(+Codes, +Exponent): `[+-]?(D+(.D*)?|.D+)`, followed
%   by `[eE][+-]?D+` if Exponent is `true`, and not a plain integer
%   unless there is an exponent.

decimal_lexical(Codes, Exponent) :-
    (   Codes = [S|Codes1],
        sign_code(S)
    ->  true
    ;   Codes1 = Codes
    ),
    mantissa(Codes1, Rest, Dot),
    (   Rest == []
    ->  Dot == true
    ;   Exponent == true,
        Rest = [E|Rest1],
        memberchk(E, `eE`),
        (   Rest1 = [S1|Rest2],
            sign_code(S1)
        ->  true
        ;   Rest2 = Rest1
        ),
        digits1(Rest2, [])
    ).

mantissa([0'.|Cs], Rest, true) :-
    !,
    digits1(Cs, Rest).
mantissa(Cs, Rest, Dot) :-
    digits1(Cs, Rest0),
    (   Rest0 = [0'.|Rest1]
    ->  Dot = true,
        digits0(Rest1, Rest)
    ;   Dot = false,
        Rest = Rest0
    ).

digits1([C|Cs], Rest) :-
    digit_code(C),
    digits0(Cs, Rest).

digits0(Cs0, Rest) :-
    (   Cs0 = [C|Cs],
        digit_code(C)
    ->  digits0(Cs, Rest)
    ;   Rest = Cs0
    ).

digit_code(C) :-
    between(0'0, 0'9, C).

%   Grammars of the XSD date, time and duration types (lexical shape
%   and field ranges; day-of-month is not checked against the month).

date_time(Zone) -->
    date_part,
    "T",
    time_part,
    zone(Zone).

date -->
    date_part,
    zone(optional).

time -->
    time_part,
    zone(optional).

g_year -->
    year,
    zone(optional).

g_year_month -->
    year,
    "-",
    two(1, 12),
    zone(optional).

g_month -->
    "--",
    two(1, 12),
    zone(optional).

g_month_day -->
    "--",
    two(1, 12),
    "-",
    two(1, 31),
    zone(optional).

g_day -->
    "---",
    two(1, 31),
    zone(optional).

date_part -->
    year,
    "-",
    two(1, 12),
    "-",
    two(1, 31).

year -->
    optional_minus,
    digit,
    digit,
    digit,
    digit,
    digits_star.

time_part -->
    two(0, 24),
    ":",
    two(0, 59),
    ":",
    two(0, 59),
    fraction.

fraction -->
    ".",
    !,
    digit,
    digits_star.
fraction -->
    [].

zone(_) -->
    "Z",
    !.
zone(_) -->
    [S],
    { sign_code(S) },
    !,
    two(0, 14),
    ":",
    two(0, 59).
zone(optional) -->
    [].

duration -->
    optional_minus,
    "P",
    duration_fields([0'Y, 0'M, 0'D], 0, N0),
    (   "T"
    ->  duration_time_fields([0'H, 0'M, 0'S], 0, N1),
        { N1 > 0 }
    ;   { N1 = 0 }
    ),
    { N0 + N1 > 0 }.

duration_fields([], N, N) -->
    [].
duration_fields([Designator|Ds], N0, N) -->
    (   digit,
        digits_star,
        [Designator]
    ->  { N1 is N0+1 }
    ;   { N1 = N0 }
    ),
    duration_fields(Ds, N1, N).

duration_time_fields([], N, N) -->
    [].
duration_time_fields([Designator|Ds], N0, N) -->
    (   digit,
        digits_star,
        (   { Designator == 0'S }
        ->  fraction
        ;   []
        ),
        [Designator]
    ->  { N1 is N0+1 }
    ;   { N1 = N0 }
    ),
    duration_time_fields(Ds, N1, N).

optional_minus -->
    "-",
    !.
optional_minus -->
    [].

two(Min, Max) -->
    [A, B],
    { digit_code(A),
      digit_code(B),
      V is (A-0'0)*10 + B-0'0,
      between(Min, Max, V)
    }.

digit -->
    [C],
    { digit_code(C) }.

digits_star -->
    [C],
    { digit_code(C) },
    !,
    digits_star.
digits_star -->
    [].


                 /*******************************
                 *        API STATEMENTS        *
                 *******************************/

%!  oro_statements(+Statements, -Triples, -Bindings) is det.
%
%   Normalise Statements (text or rdf/3 terms, see the module doc)
%   into rdf(S,P,O) triples of IRIs, literals and variables.  Bindings
%   maps the names of `?name` variables of text patterns to the
%   variables of Triples, as Name=Var pairs; variables with the same
%   name in several statements are shared.
%
%   @error syntax_error(oro_statement_tokens(N, Text)) and the other
%          errors of oro_parse_statement/2.

oro_statements(Statements, Triples, Bindings) :-
    must_be(list, Statements),
    texts_size(Statements, Size),
    bounded(Size, statement_triples(Statements, Triples, [], Bindings0)),
    reverse(Bindings0, Bindings).

%!  oro_complete_statements(+Statements, -Triples) is det.
%
%   As oro_statements/3, for Statements that must all be complete (no
%   variable) and make sense as facts: the statements a change asserts,
%   or a hypothesis.  A literal cannot be the object of a predicate of
%   RDF, RDFS or OWL whose object is a class, a property or an
%   individual (`Fork rdfs:subClassOf "x"`, `fork1 owl:sameAs 3`).
%
%   @error syntax_error(oro_statement_incomplete(Text)) if the first
%          of them that is not a fact is a pattern, Text showing it as
%          the client wrote it: its text, trimmed, or the light form of
%          a term (`x ?_ y`).
%   @error syntax_error(oro_statement_literal(Text)) if it has a
%          literal where a resource is needed.
%   @error the errors of oro_statements/3.

oro_complete_statements(Statements, Triples) :-
    oro_statements(Statements, Triples, _),
    (   first_bad(Statements, Triples, Statement, Triple, Kind)
    ->  statement_display(Statement, Triple, Text),
        bad_statement(Kind, Text, Formal),
        throw(error(syntax_error(Formal), _))
    ;   true
    ).

first_bad([Statement0|Statements], [Triple0|Triples],
          Statement, Triple, Kind) :-
    (   bad_triple(Triple0, Kind0)
    ->  Statement = Statement0,
        Triple = Triple0,
        Kind = Kind0
    ;   first_bad(Statements, Triples, Statement, Triple, Kind)
    ).

bad_triple(Triple, pattern) :-
    \+ ground(Triple),
    !.
bad_triple(rdf(_, P, literal(_)), literal) :-
    resource_object(P).

bad_statement(pattern, Text, oro_statement_incomplete(Text)).
bad_statement(literal, Text, oro_statement_literal(Text)).

%   resource_object(?P): the object of P is a class, a property, an
%   individual or a list of them, never a literal.

:- rdf_meta resource_object(r).

resource_object(rdf:type).
resource_object(rdfs:subClassOf).
resource_object(rdfs:subPropertyOf).
resource_object(rdfs:domain).
resource_object(rdfs:range).
resource_object(owl:equivalentClass).
resource_object(owl:equivalentProperty).
resource_object(owl:sameAs).
resource_object(owl:differentFrom).
resource_object(owl:inverseOf).
resource_object(owl:disjointWith).
resource_object(owl:propertyDisjointWith).
resource_object(owl:complementOf).
resource_object(owl:onProperty).
resource_object(owl:someValuesFrom).
resource_object(owl:allValuesFrom).
resource_object(owl:onClass).
resource_object(owl:intersectionOf).
resource_object(owl:unionOf).
resource_object(owl:oneOf).
resource_object(owl:propertyChainAxiom).
resource_object(owl:members).
resource_object(owl:distinctMembers).
resource_object(owl:disjointUnionOf).

%   statement_display(+Statement, +Triple, -Text): Text (a string)
%   shows Statement to the client who gave it.

statement_display(Statement, rdf(S, P, O), Text) :-
    (   atomic(Statement)                   % a string or an atom
    ->  split_string(Statement, "", " \t\r\n", [Text])
    ;   maplist(position_display, [S, P, O], Parts),
        atomic_list_concat(Parts, ' ', Atom),
        atom_string(Atom, Text)
    ).

position_display(Term, Text) :-
    (   var(Term)
    ->  Text = '?_'
    ;   oro_term_light_text(Term, Text)
    ).

statement_triples([], [], B, B).
statement_triples([Statement|Statements], [Triple|Triples], B0, B) :-
    statement_triple(Statement, Triple, B0, B1),
    statement_triples(Statements, Triples, B1, B).

statement_triple(Statement, rdf(S, P, O), B0, B) :-
    (   statement_text(Statement)
    ->  parse_statement(Statement, rdf(S0, P0, O0)),
        bind_var(S0, S, B0, B1),
        bind_var(P0, P, B1, B2),
        bind_var(O0, O, B2, B)
    ;   var(Statement)
    ->  instantiation_error(Statement)
    ;   Statement = rdf(S0, P0, O0)
    ->  oro_resource(S0, S),
        oro_resource(P0, P),
        oro_object(O0, O),
        term_literal_check(O0, O),
        B = B0
    ;   type_error(oro_statement, Statement)
    ).

%   term_literal_check(+Term, +Object): a typed literal written as such
%   in a term statement (Term, normalised as Object) has a lexical form
%   its datatype accepts, as in a text statement (check_datatype/3).
%   Numbers are typed as the parser types number tokens.

term_literal_check(Term, Object) :-
    (   nonvar(Term),
        (   Term = literal(_)
        ;   Term = _^^_
        ),
        Object = literal(type(Type, Lex))
    ->  lexical_verdict(Type, Lex, Verdict),
        (   Verdict == ok
        ->  true
        ;   oro_iri_name(Type, TypeText),       % named for the error only
            atom_string(Lex, LexString),
            datatype_verdict(Verdict, LexString, TypeText)
        )
    ;   true
    ).

statement_text(X) :-
    (   string(X)
    ->  true
    ;   atom(X)
    ).

%   bind_var(+Parsed, -Term, +Bindings0, -Bindings): Term is Parsed,
%   or for var(Name) the variable bound to Name (a new one if Name is
%   not in Bindings0 yet).

bind_var(Parsed, Term, B0, B) :-
    (   Parsed = var(Name)
    ->  (   memberchk(Name=Var0, B0)
        ->  Term = Var0,
            B = B0
        ;   B = [Name=Term|B0]
        )
    ;   Term = Parsed,
        B = B0
    ).
