:- module(oro_parse_lexer,
          [ oro_tokenize/3,             % +Text, +Delimiter, -Tokens
            oro_clean_value/2,          % +Text, -String
            tokenize/3,                 % +Text, +Delimiter, -Tokens
            clean_value/2,              % +Text, -String
            plain_text/1,               % +Text
            quote_specials/1,           % -Chars
            local_specials/1,           % -Chars
            one_part/2,                 % +Text, +Separators
            code_at/3,                  % +Index, +Text, -Code
            trim/2,                     % +Text, -Trimmed
            quoted/2,                   % +Text, -Quote
            quote_code/1,               % ?Code
            unescape/3,                 % +Text, +Original, -String
            unescape_codes/3,           % +Codes, +Original, -Codes
            string_from_text/2,         % +Text, -String
            framed/4                    % +Text, +Open, +Close, -Inner
          ]).
:- use_module(library(error)).
:- use_module(library(lists)).
:- use_module(library(settings)).
:- use_module(library(oro/parse/oro_parse_budget)).

/** <module> The lexer of ORO request parameters: tokenizer and cleanValue

This module owns the character level of ORO's parameter syntax
(ORO-SPEC §2), as oro-server 0.8.2 reads it:

  - oro_tokenize/3 is ORO's tokenizer: it splits on a delimiter only
    outside `[ ]`, `{ }` and quotes, keeping empty tokens.  A depth
    past the `max_nesting` setting raises
    `resource_error(oro_nesting(Max))` (oro_parse_budget).
  - oro_clean_value/2 is ORO's `cleanValue`: trim, drop one outer pair
    of quotes, Java-unescape.

It also exports, for the statement syntax (oro_parse_statement) and the
literals (oro_parse_literal), the scans these are built of: the test
for a text with nothing to track (plain_text/1, one_part/2), Java's
trim, the quote tests and unescaping.  See the module doc of oro_parse
for the fast paths ("Speed") and the chunked scans ("Bounded cost").
*/

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

%!  tokenize(+Text, +Delimiter:code, -Tokens:list(string)) is det.
%
%   oro_tokenize/3 for a valid Delimiter code, without the type checks
%   and the parse budget: the tokenizer the other parts of the parser
%   call on the texts they have in hand.
%
%   @error resource_error(oro_nesting(Max)) past the `max_nesting`
%          setting.

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
    setting(oro_parse:max_nesting, Max),
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

%!  code_at(+Index:positive_integer, +Text, -Code:code) is semidet.
%
%   string_code/3 in constant time.  In
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
    setting(oro_parse:max_nesting, Max),
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

%!  local_specials(-Chars:string) is det.
%!  quote_specials(-Chars:string) is det.
%
%   Chars are the characters the statement fast paths must not meet,
%   as a string: for local_specials/1 those of plain_specials(-Chars),
%   `[]{}"'\` and the codes 1-31, and `:#<^@`; for quote_specials/1
%   those of plain_specials/1 but the quotes.  (All three computed at
%   compile time.  NUL cannot be in such a set: split_string/4 reads
%   its separators up to the first NUL.)

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

%!  one_part(+Text, +Separators:string) is semidet.
%
%   Text has none of Separators and no
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

%!  clean_value(+Text, -String) is det.
%
%   oro_clean_value/2 without the type check and the parse budget.
%
%   @error syntax_error(oro_unicode_escape(Text)) as oro_clean_value/2.

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

%!  trim(+Text, -Trimmed:string) is det.
%
%   Java String.trim(), without building a code
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

%!  quoted(+Text, -Quote:code) is semidet.
%
%   Text is at least two characters long and starts and ends with the
%   same quote character, Quote.

quoted(Text, Q) :-
    string_length(Text, Len),
    Len >= 2,
    string_code(1, Text, Q),
    quote_code(Q),
    string_code(Len, Text, Q).

%!  quote_code(?Code:code) is nondet.
%
%   Code is a quote character, `"` or `'`.

quote_code(0'").
quote_code(0'\').

%!  unescape(+Text, +Original, -String) is det.
%!  unescape_codes(+Codes:list(code), +Original, -Unescaped:list(code)) is det.
%
%   String (Unescaped) is Text (Codes) Java-unescaped, as
%   oro_clean_value/2 does it.  Original is the text quoted in the
%   error term.
%
%   @error syntax_error(oro_unicode_escape(Original)) for a malformed
%          `\uXXXX` escape.

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

%!  string_from_text(+Text, -String) is det.
%
%   String is Text (an atom or a string) as a string, for error terms.

string_from_text(Text, String) :-
    (   string(Text)
    ->  String = Text
    ;   atom_string(Text, String)
    ).

%!  framed(+Text, ?Open:code, ?Close:code, -Inner:string) is semidet.
%
%   Text is at least two characters long, starts with Open and ends
%   with Close; Inner is what lies between.

framed(Text, Open, Close, Inner) :-
    string_length(Text, Len),
    Len >= 2,
    code_at(1, Text, Open),
    code_at(Len, Text, Close),
    sub_string(Text, 1, _, 1, Inner).
