:- module(oro_sparql_lexer,
          [ tokenize/2,                 % +Codes, -Tokens
            digits//1                   % -Digits
          ]).
:- use_module(library(lists)).

/** <module> The SPARQL tokenizer

Turns the text of a query into tokens for the grammar
(oro_sparql_grammar): IRIs, prefixed names, blank nodes, variables,
strings, language tags, numbers, keywords and punctuation, each with
its character offset, following the lexical productions of the W3C
SPARQL 1.1 grammar.
*/

		 /*******************************
		 *           TOKENIZER          *
		 *******************************/

%   Tokens are t(Token, Offset), Offset the 0-based character position
%   of the token in the text; the last one is t(eof, Length).  Token
%   is one of iri(Text), pname(Prefix, Local), bnode(Label),
%   var(Name), str(Atom), langtag(Tag), num(Kind, Lexical),
%   word(LowerCase, AsWritten) and punct(Atom).

%!  tokenize(+Codes, -Tokens) is det.
%
%   Tokens are the tokens of the query text Codes, each t(Token,
%   Offset) (see below), the last one t(eof, Length).
%
%   @throws oro_sparql_error(Format, Args, Offset) for a lexical error,
%           which the grammar turns into a syntax error.

tokenize(Codes, Tokens) :-
    tokens(Codes, 0, Tokens).

tokens(S0, P0, Tokens) :-
    layout(S0, S1),
    advance(S0, S1, P0, P1),
    (   S1 == []
    ->  Tokens = [t(eof, P1)]
    ;   token(T, S1, S2)
    ->  advance(S1, S2, P1, P2),
        Tokens = [t(T, P1)|Rest],
        tokens(S2, P2, Rest)
    ;   S1 = [C|_],
        (   ( C == 0'" ; C == 0'\' )
        ->  throw(oro_sparql_error("Unterminated string", [], P1))
        ;   throw(oro_sparql_error("Lexical error: unexpected character '~c'",
                                   [C], P1))
        )
    ).

advance(S0, S, P0, P) :-
    (   S0 == S
    ->  P = P0
    ;   S0 = [_|S1],
        P1 is P0 + 1,
        advance(S1, S, P1, P)
    ).

layout([C|S0], S) :-
    code_type(C, space),
    !,
    layout(S0, S).
layout([0'#|S0], S) :-
    !,
    skip_line(S0, S1),
    layout(S1, S).
layout(S, S).

skip_line([], []).
skip_line([C|S0], S) :-
    (   ( C == 0'\n ; C == 0'\r )
    ->  S = S0
    ;   skip_line(S0, S)
    ).

token(iri(IRI)) -->
    "<", iri_codes(Cs), ">",
    !,
    { atom_codes(IRI, Cs) }.
token(punct('<=')) --> "<=", !.
token(punct(<)) --> "<", !.
token(var(Name)) -->
    ( "?" ; "$" ),
    varname(Cs),
    !,
    { atom_codes(Name, Cs) }.
token(str(S)) -->
    string_literal(Cs),
    !,
    { atom_codes(S, Cs) }.
token(langtag(Tag)) -->
    "@", lang_codes(Cs),
    !,
    { atom_codes(Tag, Cs) }.
token(num(Kind, Lex)) -->
    number(Kind, Cs),
    !,
    { atom_codes(Lex, Cs) }.
token(bnode(Label)) -->
    "_:", bnode_label(Cs),
    !,
    { atom_codes(Label, Cs) }.
token(pname(Prefix, Local)) -->
    pn_prefix_opt(PCs), ":",
    !,
    pn_local_opt(LCs),
    { atom_codes(Prefix, PCs),
      atom_codes(Local, LCs)
    }.
token(word(Lower, Word)) -->
    [C], { code_type(C, csymf) },
    word_rest(Cs),
    !,
    { atom_codes(Word, [C|Cs]),
      downcase_atom(Word, Lower)
    }.
token(punct(P)) -->
    punct(P).

punct('^^') --> "^^", !.
punct('&&') --> "&&", !.
punct('||') --> "||", !.
punct('!=') --> "!=", !.
punct('>=') --> ">=", !.
punct(P) -->
    [C],
    { memberchk(C, `{}()[].,;*=>!+-/^|?`),
      char_code(P, C)
    }.

iri_codes([C|Cs]) -->
    "\\",
    code_escape(C),
    !,
    iri_codes(Cs).
iri_codes([C|Cs]) -->
    [C],
    { C > 0x20,
      \+ memberchk(C, `<>"{}|^\`\\`)
    },
    !,
    iri_codes(Cs).
iri_codes([]) --> [].

varname([C|Cs]) -->
    [C], { code_type(C, csym) },
    varname_rest(Cs).

varname_rest([C|Cs]) -->
    [C], { var_char(C) },
    !,
    varname_rest(Cs).
varname_rest([]) --> [].

%   var_char(+C): a character of PN_CHARS (and of VARNAME after its
%   first): letters, digits, `_`, U+00B7, the combining diacritical
%   marks U+0300..U+036F and U+203F..U+2040.

var_char(C) :-
    (   code_type(C, csym)
    ->  true
    ;   C == 0xB7
    ->  true
    ;   between(0x0300, 0x036F, C)
    ->  true
    ;   between(0x203F, 0x2040, C)
    ).

word_rest([C|Cs]) -->
    [C], { code_type(C, csym) },
    !,
    word_rest(Cs).
word_rest([]) --> [].

lang_codes([C|Cs]) -->
    [C], { code_type(C, alpha) },
    alpha_codes(Cs0),
    lang_subtags(Cs1),
    { append(Cs0, Cs1, Cs) }.

alpha_codes([C|Cs]) -->
    [C], { code_type(C, alpha) },
    !,
    alpha_codes(Cs).
alpha_codes([]) --> [].

lang_subtags([0'-, C|Cs]) -->
    "-", [C], { code_type(C, alnum) },
    !,
    alnum_codes(Cs0),
    lang_subtags(Cs1),
    { append(Cs0, Cs1, Cs) }.
lang_subtags([]) --> [].

alnum_codes([C|Cs]) -->
    [C], { code_type(C, alnum) },
    !,
    alnum_codes(Cs).
alnum_codes([]) --> [].

%   Strings: the four SPARQL forms, with ECHAR and \u escapes.

string_literal(Cs) --> "\"\"\"", !, long_string(0'", Cs).
string_literal(Cs) --> "'''", !, long_string(0'\', Cs).
string_literal(Cs) --> "\"", !, short_string(0'", Cs).
string_literal(Cs) --> "'", !, short_string(0'\', Cs).

long_string(Q, []) --> [Q, Q, Q], !.
long_string(Q, [C|Cs]) --> "\\", !, escape(C), long_string(Q, Cs).
long_string(Q, [C|Cs]) --> [C], long_string(Q, Cs).

short_string(Q, []) --> [Q], !.
short_string(Q, [C|Cs]) --> "\\", !, escape(C), short_string(Q, Cs).
short_string(Q, [C|Cs]) -->
    [C],
    { C \== 0'\n, C \== 0'\r },
    short_string(Q, Cs).

escape(0'\t) --> "t", !.
escape(0'\b) --> "b", !.
escape(0'\n) --> "n", !.
escape(0'\r) --> "r", !.
escape(0'\f) --> "f", !.
escape(0'") --> "\"", !.
escape(0'\') --> "'", !.
escape(0'\\) --> "\\", !.
escape(C) --> code_escape(C).

%   code_escape(-C)//: uXXXX or UXXXXXXXX after a backslash, a Unicode
%   scalar value: a UTF-16 surrogate pair written as two \u escapes is
%   one character, a lone surrogate is no character (an error).

code_escape(C) -->
    "u",
    !,
    hex_digits(4, C0),
    surrogate_pair(C0, C).
code_escape(C) -->
    "U",
    hex_digits(8, C),
    { C =< 0x10FFFF,
      \+ between(0xD800, 0xDFFF, C)
    }.

surrogate_pair(High, C) -->
    { between(0xD800, 0xDBFF, High) },
    !,
    "\\u",
    hex_digits(4, Low),
    { between(0xDC00, 0xDFFF, Low),
      C is 0x10000 + (High - 0xD800) * 0x400 + (Low - 0xDC00)
    }.
surrogate_pair(C, C) -->
    { \+ between(0xDC00, 0xDFFF, C) }.

hex_digits(N, C) -->
    hex_digits(N, 0, C).

hex_digits(0, C, C) --> !.
hex_digits(N, C0, C) -->
    [D], { code_type(D, xdigit(W)) },
    { C1 is C0*16 + W, N1 is N - 1 },
    hex_digits(N1, C1, C).

%   Numbers: INTEGER, DECIMAL, DOUBLE (signs are operators).

number(Kind, Cs) -->
    digits(D),
    (   ".", digits(F), { F \== [] }
    ->  (   exponent(E)
        ->  { Kind = double }
        ;   { E = [], Kind = decimal }
        ),
        { append([D, `.`, F, E], Cs) }
    ;   { D \== [] },
        (   ".", exponent(E)
        ->  { Kind = double, append([D, `.`, E], Cs) }
        ;   exponent(E)
        ->  { Kind = double, append(D, E, Cs) }
        ;   { Kind = integer, Cs = D }
        )
    ).

%!  digits(-Digits)// is det.
%
%   Digits is the longest (possibly empty) list of decimal digit codes
%   at the start of the input.

digits([D|T]) -->
    [D], { code_type(D, digit) },
    !,
    digits(T).
digits([]) --> [].

exponent([E|Cs]) -->
    [E], { E == 0'e ; E == 0'E },
    !,
    (   [S], { S == 0'+ ; S == 0'- }
    ->  { Cs = [S|Ds] }
    ;   { Cs = Ds }
    ),
    digits(Ds),
    { Ds \== [] }.

%   Blank node labels and prefixed names.

bnode_label([C|Cs]) -->
    [C], { code_type(C, csym) },
    dotted_rest(Cs).

%   dotted_rest(-Codes): name characters and dots, not ending with a
%   dot (trailing dots are left in the input).

dotted_rest(Cs, S0, S) :-
    name_dots(S0, Cs0, S1),
    strip_dots(Cs0, Cs, S1, S).

name_dots([C|S0], [C|Cs], S) :-
    (   var_char(C)
    ;   C == 0'-
    ;   C == 0'.
    ),
    !,
    name_dots(S0, Cs, S).
name_dots(S, [], S).

strip_dots(Cs0, Cs, S1, S) :-
    reverse(Cs0, R0),
    leading_dots(R0, R, Dots),
    reverse(R, Cs),
    append(Dots, S1, S).

leading_dots([0'.|R0], R, [0'.|Dots]) :-
    !,
    leading_dots(R0, R, Dots).
leading_dots(R, R, []).

pn_prefix_opt(Cs) -->
    [C], { code_type(C, alpha) },
    !,
    dotted_rest(Cs0),
    { Cs = [C|Cs0] }.
pn_prefix_opt([]) --> [].

pn_local_opt(Cs, S0, S) :-
    (   local_first(S0, C, S1)
    ->  local_items(S1, Items, S2),
        reverse(Items, R0),
        leading_raw_dots(R0, R, Dots),
        reverse(R, Items1),
        append(C, Items1, Cs),
        append(Dots, S2, S)
    ;   Cs = [],
        S = S0
    ).

local_first([C|S], [C], S) :-
    (   code_type(C, csym)
    ;   C == 0':
    ),
    !.
local_first(S0, Cs, S) :-
    plx(S0, Cs, S).

local_items(S0, [Item|Items], S) :-
    local_item(S0, Item, S1),
    !,
    local_items(S1, Items, S).
local_items(S, [], S).

local_item([C|S], raw(C), S) :-
    (   var_char(C)
    ;   memberchk(C, `-.:`)
    ),
    !.
local_item(S0, esc(Cs), S) :-
    plx(S0, Cs, S).

plx([0'%, A, B|S], [0'%, A, B], S) :-
    code_type(A, xdigit(_)),
    code_type(B, xdigit(_)),
    !.
plx([0'\\, C|S], [C], S) :-
    memberchk(C, `_~.-!$&'()*+,;=/?#@%`).

leading_raw_dots([raw(0'.)|R0], R, [0'.|Dots]) :-
    !,
    leading_raw_dots(R0, R, Dots).
leading_raw_dots(R0, R, []) :-
    items_codes(R0, R).

items_codes([], []).
items_codes([raw(C)|T0], [C|T]) :-
    items_codes(T0, T).
items_codes([esc(Cs)|T0], Codes) :-
    reverse(Cs, RCs),
    items_codes(T0, T),
    append(RCs, T, Codes).

