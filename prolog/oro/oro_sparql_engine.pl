:- module(oro_sparql_engine, []).
:- use_module(library(semweb/rdf_db)).
:- use_module(library(error)).
:- use_module(library(lists)).
:- use_module(library(apply)).
:- use_module(library(pairs)).
:- use_module(library(ordsets)).
:- use_module(library(assoc)).
:- use_module(library(solution_sequences)).
:- use_module(library(uri)).
:- use_module(library(date)).
:- use_module(library(debug)).
:- use_module(oro_names).
:- use_module(oro_store).
:- use_module(oro_reason).
:- use_module(oro_parse).
:- use_module(oro_knowledge, [oro_find/4]).
:- use_module(oro_query, [oro_with_time_limit/1]).

:- if(exists_source(library(pcre))).
:- use_module(library(pcre)).
:- endif.

/** <module> SPARQL 1.1 queries over the inference closure of a model

ORO clients send SPARQL: query(key, sparql) and the filters of find
(ORO-SPEC §6.3, §13.3).  This module is oro's SPARQL engine: a parser
of the query language (a tokenizer and a DCG following the productions
of the W3C SPARQL 1.1 grammar) producing a SPARQL algebra term, and an
evaluator of that algebra over oro_holds/4, the inference closure of a
model -- what find and check see.  Its API is the module oro_sparql,
which loads it on first use and calls its entry points (the PUBLIC API
section below) module-qualified.  It exports nothing: the same names
exported from here would clash with oro_sparql's wherever both modules
are imported.

    ?- oro_sparql(myself,
                  "SELECT ?x ?w WHERE { ?x a oro:Monkey ; oro:weight ?w }
                   ORDER BY DESC(?w)", R).
    R = select([x, w], [[x-'http://kb.openrobots.org#gorilla', w-literal(...)], ...]).

Supported: PREFIX and BASE (the server's prefixes are predeclared:
those of oro_prefix/2, and `:` for the default namespace), SELECT
(variables, `*`, DISTINCT, REDUCED, `(Expression AS ?v)`), ASK, basic
graph patterns with `;`, `,`, blank nodes (`_:b`, `[ ... ]`) and
collections, FILTER, OPTIONAL, UNION, MINUS, BIND, VALUES (inline and
trailing), sub-SELECT, GROUP BY, HAVING, the aggregates COUNT, SUM,
MIN, MAX, AVG, SAMPLE and GROUP_CONCAT, ORDER BY, LIMIT, OFFSET, and
property paths (`/`, `|`, `^`, `*`, `+`, `?`, `!`).  Expressions have
the whole grammar of SPARQL 1.1: `||`, `&&`, comparisons, IN and NOT
IN, arithmetic, EXISTS and NOT EXISTS, and the functions STR, LANG,
LANGMATCHES, DATATYPE, BOUND, IRI, URI, isIRI, isURI, isBLANK,
isLITERAL, isNUMERIC, REGEX, REPLACE, CONTAINS, STRSTARTS, STRENDS,
STRBEFORE, STRAFTER, STRLEN, SUBSTR, UCASE, LCASE, CONCAT,
ENCODE_FOR_URI, STRLANG, STRDT, ABS, CEIL, FLOOR, ROUND, IF, COALESCE,
sameTerm and the XSD casts (xsd:string, xsd:integer, xsd:decimal,
xsd:double, xsd:float, xsd:boolean).  Not supported (a clear parse
error): CONSTRUCT, DESCRIBE, FROM, GRAPH, SERVICE, updates and the
date, hash and random functions.

Semantics follow the SPARQL 1.1 specification: errors in expressions
make a FILTER false, `||` and `&&` follow the three-valued logic of
§17.2, comparisons follow the operator mapping (numbers by value with
type promotion integer < decimal < float < double, simple literals and
xsd:string as strings, booleans, xsd:dateTime, RDF term equality
otherwise, a type error for literals of incomparable types), FILTER
scope is the group, OPTIONAL filters see both sides, EXISTS substitutes
the current solution.  Two ORO-isms come from the reasoning layer: a
constant literal in a triple pattern matches by value (`12` matches
`"12"^^xsd:int`, strings ignore language tags), and a relative IRI
without BASE is a name in the default namespace (`<fish>` is
oro:fish).  Regular expressions are PCRE (library(pcre)), which covers
the XPath syntax SPARQL uses; the flags `i`, `s`, `m`, `x` and `q` are
supported (without library(pcre), REGEX and REPLACE are expression
errors).  REDUCED keeps every row, as ALL does.  With both ends
unbound, the zero-length matches of `p*` and `p?` are the nodes the
path itself touches, not every node of the model.

Evaluation:

  - A basic graph pattern runs its triple patterns in the order of a
    plan: greedily the pattern expected to have the fewest solutions
    given the variables bound so far, estimated with
    rdf_estimate_complexity/4 on the query's constants, summed over the
    sub-properties of the predicate (or the sub-classes of the class
    for rdf:type), and with rdf_db's branch factors for variables bound
    by earlier patterns.  Patterns whose parts are all bound are checks;
    they run before any pattern that binds a variable, cheapest and
    most selective first.  So a query with several patterns starts from
    its most selective one and does not scan.  A plan is made once per
    query for each set of variables bound on entry.
  - The conjuncts of a FILTER over a basic graph pattern are tested
    inside it, as soon as their variables are bound; operators and
    functions applied to constants are evaluated once.
  - Solutions flow into the next pattern of a join (sideways
    information passing), but only the variables a pattern is certain
    to bind are pushed into it, so FILTER scoping, OPTIONAL and MINUS
    keep their bottom-up meaning.  Without ORDER BY or aggregates,
    solutions stream: LIMIT and ASK stop the evaluation early.
  - A query, its parsing included, is bounded by the setting
    `oro_query:time_limit` (seconds, default 5; 0 for none), as finds
    of several patterns are: past it, evaluation stops with
    `error(resource_error(oro_query_time_limit(Seconds)), _)`.  Queries
    run in the caller's thread (a server worker), so other clients are
    not held up.

Measured (bench/bench_sparql.pl, SWI-Prolog 9.0.4, AMD EPYC, 100k
asserted triples over the common-sense ontology, medians): a join of 3
patterns (23 rows) 4.5 ms, of 4 patterns 7-8 ms, of 5 patterns with an
inferred type and property (213 rows) 11 ms; a find with 4 patterns and
4 filters 34 ms (the 4 patterns alone through oro_find/4: 21 ms);
parsing a 5-pattern query 0.33 ms.  Most of a join is the reasoner's
own work (oro_holds/4 checks, 4 to 8 us each).

Errors are ISO-shaped: a malformed query raises
`error(syntax_error(oro_sparql(Message, Position)), _)` where Message
is one line naming the line and column and Position is the 0-based
character offset in the query text.
*/

:- rdf_meta
    boolean_term(+, o),
    xsd_string(r),
    xsd_boolean(r),
    kind_type(?, r),
    date_type(r),
    cast_type(r, -),
    type_literal(r, +, -).

		 /*******************************
		 *           PUBLIC API         *
		 *******************************/

%!  oro_sparql_parse(+Text, -Query) is det.
%
%   Called by oro_sparql:oro_sparql_parse/2, which documents it.

oro_sparql_parse(Text, Query) :-
    must_be(text, Text),
    parse_text(query, Text, Query).

%!  oro_sparql(+Model, +Text, -Result) is det.
%
%   Called by oro_sparql:oro_sparql/3, which documents it.

oro_sparql(Model0, Text, Result) :-
    oro_resolve_model(Model0, Model),
    oro_with_time_limit(( oro_sparql_parse(Text, Query),
                          run_query(Model, Query, Result)
                        )).

%!  oro_sparql_json(+Model, +Text, -JSON) is det.
%
%   Called by oro_sparql:oro_sparql_json/3, which documents it.

oro_sparql_json(Model, Text, JSON) :-
    oro_sparql(Model, Text, Result),
    result_json(Result, JSON).

%!  oro_query_values(+Model, +Key, +Text, -Values) is det.
%
%   Called by oro_sparql:oro_query_values/4, which documents it.

oro_query_values(Model0, Key, Text, Values) :-
    oro_resolve_model(Model0, Model),
    must_be(text, Key),
    key_name(Key, Name),
    oro_with_time_limit(( oro_sparql_parse(Text, Query),
                          (   Query = select(_, _, _, _)
                          ->  true
                          ;   sparql_error("a SELECT query is expected", 0, Text)
                          ),
                          run_query(Model, Query, select(_, Rows))
                        )),
    findall(V, ( member(Row, Rows),
                 memberchk(Name-V, Row),
                 \+ rdf_is_bnode(V)
               ), Vs),
    sort(Vs, Values).

key_name(Key, Name) :-
    atom_string(Atom, Key),
    normalize_space(atom(Trimmed), Atom),
    (   ( sub_atom(Trimmed, 0, 1, _, ?) ; sub_atom(Trimmed, 0, 1, _, $) )
    ->  sub_atom(Trimmed, 1, _, 0, Name)
    ;   Name = Trimmed
    ).

%!  oro_find(+Model, +Var, +Patterns, +Filters, -Values) is det.
%
%   Called by oro_sparql:oro_find/5, which documents it.

oro_find(Model0, Var, Patterns, Filters, Values) :-
    oro_resolve_model(Model0, Model),
    must_be(list, Patterns),
    must_be(list(text), Filters),
    (   Filters == []
    ->  oro_find(Model, Var, Patterns, Values)
    ;   Patterns == []
    ->  (   text(Var)
        ->  find_variable_name(Var, _)
        ;   true
        ),
        Values = []
    ;   copy_term(Var-Patterns, Var1-Patterns1),
        oro_statements(Patterns1, Triples, Bindings),
        (   text(Var1)
        ->  find_variable_name(Var1, Name)
        ;   must_be(var, Var1),
            Name = '_:find',
            Var1 = var(Name)
        ),
        maplist(bind_name, Bindings),
        term_variables(Triples, Anonymous),
        foldl(name_anonymous, Anonymous, 1, _),
        Pattern = filter(Filter, bgp(Triples)),
        Query = select([var(Name)], all, Pattern,
                       mods(false, none, [], [], 0, inf, none)),
        oro_with_time_limit(( maplist(parse_filter, Filters, Exprs),
                              conjunction(Exprs, Filter),
                              run_query(Model, Query, select(_, Rows))
                            )),
        findall(V, ( member(Row, Rows),
                     memberchk(Name-V, Row),
                     \+ rdf_is_bnode(V)
                   ), Vs),
        sort(Vs, Values)
    ).

text(X) :-
    (   string(X)
    ->  true
    ;   atom(X)
    ).

find_variable_name(Text, Name) :-
    key_name(Text, Name),
    (   Name == ''
    ->  domain_error(oro_variable, Text)
    ;   true
    ).

bind_name(Name=var(Name)).

name_anonymous(var(Name), N0, N) :-
    format(atom(Name), '_:a~d', [N0]),
    N is N0 + 1.

parse_filter(Text, Expr) :-
    parse_text(expression, Text, Expr).

		 /*******************************
		 *           MESSAGES           *
		 *******************************/

:- multifile prolog:error_message//1.

prolog:error_message(syntax_error(oro_sparql(Message, _Position))) -->
    [ 'SPARQL: ~w'-[Message] ].

		 /*******************************
		 *           TOKENIZER          *
		 *******************************/

%   Tokens are t(Token, Offset), Offset the 0-based character position
%   of the token in the text; the last one is t(eof, Length).  Token
%   is one of iri(Text), pname(Prefix, Local), bnode(Label),
%   var(Name), str(Atom), langtag(Tag), num(Kind, Lexical),
%   word(LowerCase, AsWritten) and punct(Atom).

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

var_char(C) :-
    (   code_type(C, csym)
    ->  true
    ;   C == 0xB7
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
escape(C) --> "u", !, hex_digits(4, C).
escape(C) --> "U", hex_digits(8, C).

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

		 /*******************************
		 *       PARSING: DRIVER        *
		 *******************************/

%   parse_text(+What, +Text, -Term): What is `query` or `expression`.

parse_text(What, Text, Term) :-
    string_codes(Text, Codes),
    catch(parse_codes(What, Codes, Term),
          oro_sparql_error(Format, Args, Pos),
          ( format(string(Msg), Format, Args),
            sparql_error(Msg, Pos, Codes)
          )).

parse_codes(What, Codes, Term) :-
    tokenize(Codes, Tokens),
    initial_state(St),
    nb_setval(oro_sparql_far, far(-1, [])),
    (   parse_tokens(What, St, Term, Tokens)
    ->  true
    ;   nb_getval(oro_sparql_far, far(P, Expected)),
        failure_message(P, Expected, Tokens, Msg),
        throw(oro_sparql_error("~w", [Msg], P))
    ).

parse_tokens(query, St, Query, Tokens) :-
    phrase(query_unit(St, Query), Tokens).
parse_tokens(expression, St, Expr, Tokens) :-
    phrase(( expression(St, Expr), tok(eof) ), Tokens).

initial_state(st(Prefixes, none, counter(0), no_aggregates)) :-
    oro_default_namespace(Default),
    findall(P-NS, oro_prefix(P, NS), Prefixes0),
    Prefixes = [''-Default|Prefixes0].

failure_message(P0, Expected, Tokens, Msg) :-
    (   P0 < 0
    ->  Tokens = [t(T, _)|_]
    ;   memberchk(t(T, P0), Tokens)
    ),
    token_text(T, Found),
    exclude(generic_expectation, Expected, Expected1),
    maplist(expected_text, Expected1, Texts0),
    sort(Texts0, Texts),
    (   Texts == []
    ->  format(string(Msg), 'Encountered ~w', [Found])
    ;   atomic_list_concat(Texts, ', ', ExpText),
        format(string(Msg), 'Encountered ~w, was expecting one of: ~w',
               [Found, ExpText])
    ).

%   sparql_error(+Message, +Position, +Text): throw the syntax error.

sparql_error(Msg, Pos, Text) :-
    (   is_list(Text)
    ->  Codes = Text
    ;   string_codes(Text, Codes)
    ),
    line_column(Codes, Pos, Line, Column),
    format(string(Message), 'Line ~d, column ~d: ~w', [Line, Column, Msg]),
    throw(error(syntax_error(oro_sparql(Message, Pos)), _)).

line_column(Codes, Pos, Line, Column) :-
    line_column(Codes, Pos, 1, 1, Line, Column).

line_column(_, 0, L, C, L, C) :- !.
line_column([], _, L, C, L, C) :- !.
line_column([X|Xs], N, L0, C0, L, C) :-
    N1 is N - 1,
    (   X == 0'\n
    ->  L1 is L0 + 1,
        line_column(Xs, N1, L1, 1, L, C)
    ;   C1 is C0 + 1,
        line_column(Xs, N1, L0, C1, L, C)
    ).

token_text(eof, 'the end of the query') :- !.
token_text(iri(I), T) :- !, format(atom(T), '<~w>', [I]).
token_text(pname(P, L), T) :- !, format(atom(T), '"~w:~w"', [P, L]).
token_text(bnode(L), T) :- !, format(atom(T), '"_:~w"', [L]).
token_text(var(N), T) :- !, format(atom(T), '"?~w"', [N]).
token_text(str(S), T) :- !, format(atom(T), 'the string "~w"', [S]).
token_text(langtag(L), T) :- !, format(atom(T), '"@~w"', [L]).
token_text(num(_, L), T) :- !, format(atom(T), '"~w"', [L]).
token_text(word(_, W), T) :- !, format(atom(T), '"~w"', [W]).
token_text(punct(P), T) :- format(atom(T), '"~w"', [P]).

generic_expectation(word(W, _)) :-
    var(W).
generic_expectation(punct(P)) :-
    var(P).

expected_text(eof, 'the end of the query') :- !.
expected_text(iri(_), 'an IRI') :- !.
expected_text(pname(_, _), 'a prefixed name') :- !.
expected_text(bnode(_), 'a blank node') :- !.
expected_text(var(_), 'a variable') :- !.
expected_text(str(_), 'a string') :- !.
expected_text(langtag(_), 'a language tag') :- !.
expected_text(num(_, _), 'a number') :- !.
expected_text(word(W, _), T) :-
    !,
    upcase_atom(W, U),
    format(atom(T), '"~w"', [U]).
expected_text(punct(P), T) :- format(atom(T), '"~w"', [P]).

%   Token primitives.  A token that does not match is noted as
%   expected at its position; the failure message names the furthest
%   position reached and what was expected there.

tok(T, [t(T0, P)|S], S) :-
    (   T0 = T
    ->  true
    ;   note_expected(P, T),
        fail
    ).

tokp(T, P, [t(T0, P)|S], S) :-
    (   T0 = T
    ->  true
    ;   note_expected(P, T),
        fail
    ).

kw(K) --> tok(word(K, _)).

peek_kw(K, S, S) :-
    S = [t(word(K, _), _)|_].

%   quiet_word(+Keyword, -Pos): the next token is Keyword (not noted
%   as expected: for keywords that are recognised only to be refused).

quiet_word(K, P, [t(word(K, _), P)|S], S).

here(P, S, S) :-
    S = [t(_, P)|_].

note_expected(P, T) :-
    nb_getval(oro_sparql_far, far(P0, Ts0)),
    (   P > P0
    ->  nb_setval(oro_sparql_far, far(P, [T]))
    ;   P =:= P0,
        \+ ( member(T0, Ts0), T0 =@= T )
    ->  nb_setval(oro_sparql_far, far(P, [T|Ts0]))
    ;   true
    ).

semantic_error(Format, Args, P) :-
    throw(oro_sparql_error(Format, Args, P)).

		 /*******************************
		 *      PARSING: QUERIES        *
		 *******************************/

query_unit(St0, Query) -->
    prologue(St0, St),
    (   kw(select)
    ->  select_query(St, Query0)
    ;   kw(ask)
    ->  ask_query(St, Query0)
    ;   unsupported_form
    ),
    values_clause(St, Values),
    { add_values(Query0, Values, Query) },
    tok(eof).

unsupported_form -->
    tokp(word(W, Word), P),
    { memberchk(W, [construct, describe, insert, delete, load, clear,
                    create, drop, with]),
      upcase_atom(Word, Up),
      semantic_error("~w is not supported (only SELECT and ASK queries)",
                     [Up], P)
    }.

add_values(select(Pr, D, P, mods(A, G, H, O, Off, L, _)), Values,
           select(Pr, D, P, mods(A, G, H, O, Off, L, Values))).
add_values(ask(P, mods(A, G, H, O, Off, L, _)), Values,
           ask(P, mods(A, G, H, O, Off, L, Values))).

prologue(St0, St) -->
    (   kw(base)
    ->  tokp(iri(IRI0), P),
        { resolve_iri(St0, IRI0, P, IRI),
          St0 = st(Prefixes, _, C, A),
          St1 = st(Prefixes, IRI, C, A)
        },
        prologue(St1, St)
    ;   kw(prefix)
    ->  tokp(pname(Prefix, Local), P),
        { Local == ''
        ->  true
        ;   semantic_error("PREFIX expects a prefix name ending with ':'",
                           [], P)
        },
        tokp(iri(IRI0), PI),
        { resolve_iri(St0, IRI0, PI, NS),
          St0 = st(Prefixes0, B, C, A),
          St1 = st([Prefix-NS|Prefixes0], B, C, A)
        },
        prologue(St1, St)
    ;   { St = St0 }
    ).

%   SELECT: the projection, WHERE clause and solution modifiers.

select_query(St, Query) -->
    select_clause(St, Distinct, Proj0),
    dataset_clauses,
    where_clause(St, Pattern),
    solution_modifier(St, Mods0),
    { make_select(Proj0, Distinct, Pattern, Mods0, Query) }.

select_clause(St, Distinct, Proj) -->
    (   kw(distinct)
    ->  { Distinct = distinct }
    ;   kw(reduced)
    ->  { Distinct = reduced }
    ;   { Distinct = all }
    ),
    (   tokp(punct(*), P)
    ->  { Proj = star(P) }
    ;   { aggregates_allowed(St, StA) },
        projection_item(StA, Item),
        projection_items(StA, Items),
        { Proj = [Item|Items] }
    ).

projection_items(St, [Item|Items]) -->
    projection_item(St, Item),
    !,
    projection_items(St, Items).
projection_items(_, []) --> [].

projection_item(_, var(N)-P) -->
    tokp(var(N), P),
    !.
projection_item(St, as(E, N)-P) -->
    tok(punct('(')),
    expression(St, E),
    kw(as),
    tokp(var(N), P),
    tok(punct(')')).

dataset_clauses -->
    (   quiet_word(from, P)
    ->  { semantic_error("FROM is not supported (one model, no named graphs)",
                         [], P) }
    ;   []
    ).

where_clause(St, Pattern) -->
    (   kw(where)
    ->  []
    ;   []
    ),
    group_graph_pattern(St, Pattern).

ask_query(St, ask(Pattern, Mods)) -->
    dataset_clauses,
    where_clause(St, Pattern),
    solution_modifier(St, Mods0),
    { Mods0 = m(Group, Having, Order, Offset, Limit),
      (   ( Group \== none ; contains_aggregate(Having-Order) )
      ->  Agg = true
      ;   Agg = false
      ),
      Mods = mods(Agg, Group, Having, Order, Offset, Limit, none)
    }.

solution_modifier(St, m(Group, Having, Order, Offset, Limit)) -->
    group_clause(St, Group),
    { aggregates_allowed(St, StA) },
    having_clause(StA, Having),
    order_clause(StA, Order),
    limit_offset(Offset, Limit).

group_clause(St, Group) -->
    (   kw(group)
    ->  kw(by),
        group_condition(St, C),
        group_conditions(St, Cs),
        { Group = [C|Cs] }
    ;   { Group = none }
    ).

group_conditions(St, [C|Cs]) -->
    group_condition(St, C),
    !,
    group_conditions(St, Cs).
group_conditions(_, []) --> [].

group_condition(_, key(var(N), none)) -->
    tok(var(N)),
    !.
group_condition(St, key(E, As)) -->
    tok(punct('(')),
    !,
    expression(St, E),
    (   kw(as)
    ->  tok(var(As))
    ;   { As = none }
    ),
    tok(punct(')')).
group_condition(St, key(E, none)) -->
    function_constraint(St, E).

having_clause(St, Having) -->
    (   kw(having)
    ->  constraint(St, C),
        constraints(St, Cs),
        { Having = [C|Cs] }
    ;   { Having = [] }
    ).

constraints(St, [C|Cs]) -->
    constraint(St, C),
    !,
    constraints(St, Cs).
constraints(_, []) --> [].

order_clause(St, Order) -->
    (   kw(order)
    ->  kw(by),
        order_condition(St, C),
        order_conditions(St, Cs),
        { Order = [C|Cs] }
    ;   { Order = [] }
    ).

order_conditions(St, [C|Cs]) -->
    order_condition(St, C),
    !,
    order_conditions(St, Cs).
order_conditions(_, []) --> [].

order_condition(St, asc(E)) -->
    kw(asc),
    !,
    bracketted_expression(St, E).
order_condition(St, desc(E)) -->
    kw(desc),
    !,
    bracketted_expression(St, E).
order_condition(_, asc(var(N))) -->
    tok(var(N)),
    !.
order_condition(St, asc(E)) -->
    constraint(St, E).

limit_offset(Offset, Limit) -->
    (   kw(limit)
    ->  integer_value(Limit),
        (   kw(offset)
        ->  integer_value(Offset)
        ;   { Offset = 0 }
        )
    ;   kw(offset)
    ->  integer_value(Offset),
        (   kw(limit)
        ->  integer_value(Limit)
        ;   { Limit = inf }
        )
    ;   { Offset = 0, Limit = inf }
    ).

integer_value(N) -->
    tok(num(integer, Lex)),
    { atom_number(Lex, N) }.

values_clause(St, Values) -->
    (   kw(values)
    ->  data_block(St, Values)
    ;   { Values = none }
    ).

%   make_select(+Proj0, +Distinct, +Pattern, +Mods0, -Query): check
%   the projection and build the query term.

make_select(star(P), Distinct, Pattern, m(Group, Having, Order, Off, Lim),
            select(Proj, Distinct, Pattern,
                   mods(Agg, Group, Having, Order, Off, Lim, none))) :-
    !,
    (   ( Group \== none ; contains_aggregate(Having-Order) )
    ->  semantic_error("SELECT * is not allowed with GROUP BY or aggregates",
                       [], P)
    ;   Agg = false
    ),
    in_scope(Pattern, Vars),
    findall(var(V), member(V, Vars), Proj).
make_select(Items, Distinct, Pattern, m(Group, Having, Order, Off, Lim),
            select(Proj, Distinct, Pattern,
                   mods(Agg, Group, Having, Order, Off, Lim, none))) :-
    pairs_keys(Items, Proj),
    (   ( Group \== none ; contains_aggregate(Proj-Having-Order) )
    ->  Agg = true,
        group_names(Group, Allowed0),
        foldl(check_grouped_item, Items, Allowed0, _)
    ;   Agg = false
    ),
    in_scope(Pattern, InScope),
    foldl(check_new_variable, Items, InScope, _).

group_names(none, []).
group_names([H|T], Names) :-
    findall(N, ( member(key(E, As), [H|T]),
                 (   As \== none
                 ->  N = As
                 ;   E = var(N)
                 )
               ), Names0),
    sort(Names0, Names).

check_grouped_item(var(N)-P, Allowed, Allowed) :-
    (   memberchk(N, Allowed)
    ->  true
    ;   semantic_error("Non-group key variable in SELECT: ?~w", [N], P)
    ).
check_grouped_item(as(E, N)-P, Allowed, [N|Allowed]) :-
    free_variables(E, Vars),
    (   member(V, Vars),
        \+ memberchk(V, Allowed)
    ->  semantic_error("Non-group key variable in SELECT: ?~w", [V], P)
    ;   true
    ).

check_new_variable(var(N)-_, Seen, [N|Seen]).
check_new_variable(as(_, N)-P, Seen, [N|Seen]) :-
    (   memberchk(N, Seen)
    ->  semantic_error("Variable ?~w is already in scope and cannot be \c
                        bound by AS", [N], P)
    ;   true
    ).

%   free_variables(+Expr, -Names): the variables of Expr outside
%   aggregates and EXISTS.

free_variables(E, Names) :-
    phrase(free_vars(E), Names0),
    sort(Names0, Names).

free_vars(var(N)) --> !, [N].
free_vars(const(_)) --> !.
free_vars(agg(_, _, _, _)) --> !.
free_vars(exists(_)) --> !.
free_vars(not_exists(_)) --> !.
free_vars(bound(N)) --> !, [N].
free_vars(E) -->
    { compound(E),
      !,
      E =.. [_|Args]
    },
    free_vars_list(Args).
free_vars(_) --> [].

free_vars_list([]) --> [].
free_vars_list([H|T]) -->
    (   { is_list(H) }
    ->  free_vars_list(H)
    ;   free_vars(H)
    ),
    free_vars_list(T).

contains_aggregate(Term) :-
    sub_term(Sub, Term),
    compound(Sub),
    Sub = agg(_, _, _, _),
    !.

aggregates_allowed(st(P, B, C, _), st(P, B, C, aggregates)).

no_aggregates(st(P, B, C, _), st(P, B, C, no_aggregates)).

		 /*******************************
		 *   PARSING: GRAPH PATTERNS    *
		 *******************************/

group_graph_pattern(St0, Pattern) -->
    { no_aggregates(St0, St) },
    tok(punct('{')),
    (   peek_kw(select)
    ->  kw(select),
        sub_select(St, Query),
        { Pattern = subselect(Query) }
    ;   group_elements(St, Elems),
        { translate_group(Elems, Pattern) }
    ),
    tok(punct('}')).

sub_select(St, Query) -->
    select_query(St, Query0),
    values_clause(St, Values),
    { add_values(Query0, Values, Query) }.

group_elements(St, Elems) -->
    triples_block_opt(St, Elems, Elems1),
    group_elements_rest(St, Elems1).

group_elements_rest(St, Elems) -->
    (   pattern_not_triples(St, E)
    ->  { Elems = [E|Elems1] },
        (   tok(punct('.'))
        ->  []
        ;   []
        ),
        triples_block_opt(St, Elems1, Elems2),
        group_elements_rest(St, Elems2)
    ;   { Elems = [] }
    ).

triples_block_opt(St, Elems, Tail) -->
    (   triples_block(St, Triples)
    ->  { Elems = [bgp(Triples)|Tail] }
    ;   { Elems = Tail }
    ).

triples_block(St, Triples) -->
    triples_same_subject(St, Triples0),
    (   tok(punct('.'))
    ->  (   triples_block(St, Triples1)
        ->  []
        ;   { Triples1 = [] }
        )
    ;   { Triples1 = [] }
    ),
    { append(Triples0, Triples1, Triples) }.

pattern_not_triples(St, E) -->
    (   peek_punct('{')
    ->  group_or_union(St, P),
        { E = group(P) }
    ;   kw(optional)
    ->  group_graph_pattern(St, P),
        { E = optional(P) }
    ;   kw(minus)
    ->  group_graph_pattern(St, P),
        { E = minus(P) }
    ;   kw(filter)
    ->  constraint(St, C),
        { E = filter(C) }
    ;   kw(bind)
    ->  tok(punct('(')),
        expression(St, X),
        kw(as),
        tokp(var(N), P),
        tok(punct(')')),
        { E = bind(X, N, P) }
    ;   kw(values)
    ->  data_block(St, E)
    ;   tokp(word(W, Word), P),
        { memberchk(W, [graph, service]),
          upcase_atom(Word, Up),
          semantic_error("~w is not supported (one model, no named graphs)",
                         [Up], P)
        }
    ).

peek_punct(X, S, S) :-
    S = [t(T, P)|_],
    (   T == punct(X)
    ->  true
    ;   note_expected(P, punct(X)),
        fail
    ).

group_or_union(St, Pattern) -->
    group_graph_pattern(St, P0),
    union_rest(St, P0, Pattern).

union_rest(St, P0, Pattern) -->
    (   kw(union)
    ->  group_graph_pattern(St, P1),
        union_rest(St, union(P0, P1), Pattern)
    ;   { Pattern = P0 }
    ).

%   translate_group(+Elements, -Pattern): SPARQL 1.1 §18.2.2.6.

translate_group(Elems, Pattern) :-
    foldl(group_element, Elems, g(bgp([]), []), g(G, Filters)),
    (   Filters == []
    ->  Pattern = G
    ;   conjunction(Filters, F),
        Pattern = filter(F, G)
    ).

group_element(filter(E), g(G, Fs), g(G, Fs1)) :-
    append(Fs, [E], Fs1).
group_element(optional(P), g(G, Fs), g(left_join(G, A, F), Fs)) :-
    (   P = filter(F0, A0)
    ->  A = A0,
        F = F0
    ;   A = P,
        true_expression(F)
    ).
group_element(minus(P), g(G, Fs), g(minus(G, P), Fs)).
group_element(bind(E, N, Pos), g(G, Fs), g(extend(G, N, E), Fs)) :-
    in_scope(G, Vars),
    (   memberchk(N, Vars)
    ->  semantic_error("BIND: variable ?~w is already in scope", [N], Pos)
    ;   true
    ).
group_element(bgp(Ts), g(G, Fs), g(G1, Fs)) :-
    join_patterns(G, bgp(Ts), G1).
group_element(group(P), g(G, Fs), g(G1, Fs)) :-
    join_patterns(G, P, G1).
group_element(values(Vs, Rows), g(G, Fs), g(G1, Fs)) :-
    join_patterns(G, values(Vs, Rows), G1).

join_patterns(bgp([]), P, P) :- !.
join_patterns(bgp(A), bgp(B), bgp(C)) :- !, append(A, B, C).
join_patterns(G, P, join(G, P)).

true_expression(const(literal(type(T, true)))) :-
    rdf_equal(xsd:boolean, T).

conjunction([E], E) :- !.
conjunction([E|Es], and(E, C)) :-
    conjunction(Es, C).

%   in_scope(+Pattern, -Names): the variables of Pattern that may be
%   bound, in order of first appearance; hidden (blank node) variables
%   are left out.

in_scope(Pattern, Names) :-
    phrase(scope(Pattern), Names0),
    list_to_set(Names0, Names).

scope(bgp(Ts)) --> scope_triples(Ts).
scope(join(A, B)) --> scope(A), scope(B).
scope(left_join(A, B, _)) --> scope(A), scope(B).
scope(union(A, B)) --> scope(A), scope(B).
scope(minus(A, _)) --> scope(A).
scope(filter(_, A)) --> scope(A).
scope(extend(A, N, _)) --> scope(A), [N].
scope(values(Vs, _)) --> list(Vs).
scope(subselect(select(Proj, _, _, _))) --> projected(Proj).

scope_triples([]) --> [].
scope_triples([T|Ts]) -->
    { T =.. [_, S, P, O] },
    scope_node(S), scope_node(P), scope_node(O),
    scope_triples(Ts).

scope_node(var(N)) -->
    { \+ hidden_variable(N) },
    !,
    [N].
scope_node(_) --> [].

projected([]) --> [].
projected([var(N)|T]) --> [N], projected(T).
projected([as(_, N)|T]) --> [N], projected(T).

list([]) --> [].
list([H|T]) --> [H], list(T).

hidden_variable(N) :-
    sub_atom(N, 0, _, _, '_:').

		 /*******************************
		 *      PARSING: TRIPLES        *
		 *******************************/

triples_same_subject(St, Triples) -->
    (   var_or_term(St, S)
    ->  property_list_not_empty(St, S, Triples)
    ;   triples_node(St, S, Triples0),
        property_list(St, S, Triples1),
        { append(Triples0, Triples1, Triples) }
    ).

property_list(St, S, Triples) -->
    (   property_list_not_empty(St, S, Triples0)
    ->  { Triples = Triples0 }
    ;   { Triples = [] }
    ).

property_list_not_empty(St, S, Triples) -->
    verb(St, V),
    object_list(St, S, V, Triples0),
    property_list_rest(St, S, Triples1),
    { append(Triples0, Triples1, Triples) }.

property_list_rest(St, S, Triples) -->
    (   tok(punct(;))
    ->  (   verb(St, V)
        ->  object_list(St, S, V, Triples0),
            property_list_rest(St, S, Triples1),
            { append(Triples0, Triples1, Triples) }
        ;   property_list_rest(St, S, Triples)
        )
    ;   { Triples = [] }
    ).

verb(_, var(N)) -->
    tok(var(N)),
    !.
verb(St, Path) -->
    path(St, Path).

object_list(St, S, V, Triples) -->
    object(St, S, V, Triples0),
    (   tok(punct(','))
    ->  object_list(St, S, V, Triples1)
    ;   { Triples1 = [] }
    ),
    { append(Triples0, Triples1, Triples) }.

object(St, S, V, Triples) -->
    graph_node(St, O, Triples0),
    { verb_triples(St, S, V, O, Triples1),
      append(Triples1, Triples0, Triples)
    }.

verb_triples(_, S, var(N), O, [rdf(S, var(N), O)]) :- !.
verb_triples(St, S, Path, O, Triples) :-
    normalize_path(Path, Path1),
    path_triples(St, S, Path1, O, Triples).

graph_node(St, Node, Triples) -->
    (   var_or_term(St, Node)
    ->  { Triples = [] }
    ;   triples_node(St, Node, Triples)
    ).

var_or_term(_, var(N)) -->
    tok(var(N)),
    !.
var_or_term(St, T) -->
    graph_term(St, T).

graph_term(St, T) -->
    (   iri(St, T)
    ->  []
    ;   rdf_literal(St, T)
    ->  []
    ;   numeric_literal(T)
    ->  []
    ;   boolean_literal(T)
    ->  []
    ;   tok(bnode(L))
    ->  { atom_concat('_:b_', L, N),
          T = var(N)
        }
    ;   tok(punct('[')), tok(punct(']'))
    ->  { fresh_variable(St, T) }
    ;   tok(punct('(')), tok(punct(')'))
    ->  { rdf_equal(rdf:nil, T) }
    ).

triples_node(St, Node, Triples) -->
    (   tok(punct('['))
    ->  { fresh_variable(St, Node) },
        property_list_not_empty(St, Node, Triples),
        tok(punct(']'))
    ;   tok(punct('('))
    ->  graph_node(St, First, Triples0),
        collection_nodes(St, Nodes, Triples1),
        tok(punct(')')),
        { collection_triples(St, [First|Nodes], Node, Triples2),
          append([Triples0, Triples1, Triples2], Triples)
        }
    ).

collection_nodes(St, [N|Ns], Triples) -->
    graph_node(St, N, Triples0),
    !,
    collection_nodes(St, Ns, Triples1),
    { append(Triples0, Triples1, Triples) }.
collection_nodes(_, [], []) --> [].

collection_triples(_, [], Nil, []) :-
    rdf_equal(rdf:nil, Nil).
collection_triples(St, [X|Xs], Node,
                   [rdf(Node, First, X), rdf(Node, Rest, Next)|Triples]) :-
    rdf_equal(rdf:first, First),
    rdf_equal(rdf:rest, Rest),
    fresh_variable(St, Node),
    collection_triples(St, Xs, Next, Triples).

fresh_variable(st(_, _, Counter, _), var(Name)) :-
    arg(1, Counter, N0),
    N is N0 + 1,
    nb_setarg(1, Counter, N),
    format(atom(Name), '_:h~d', [N]).

		 /*******************************
		 *    PARSING: PROPERTY PATHS   *
		 *******************************/

%   Paths: link(IRI), inv(P), seq(P, Q), alt(P, Q), star(P), plus(P),
%   opt(P), nps(Forward, Backward) (a negated property set; `none` for
%   an absent direction).

path(St, Path) -->
    path_sequence(St, P0),
    path_alternatives(St, P0, Path).

path_alternatives(St, P0, Path) -->
    (   tok(punct('|'))
    ->  path_sequence(St, P1),
        path_alternatives(St, alt(P0, P1), Path)
    ;   { Path = P0 }
    ).

path_sequence(St, Path) -->
    path_elt_or_inverse(St, P0),
    path_sequence_rest(St, P0, Path).

path_sequence_rest(St, P0, Path) -->
    (   tok(punct(/))
    ->  path_elt_or_inverse(St, P1),
        path_sequence_rest(St, seq(P0, P1), Path)
    ;   { Path = P0 }
    ).

path_elt_or_inverse(St, Path) -->
    (   tok(punct(^))
    ->  path_elt(St, P),
        { Path = inv(P) }
    ;   path_elt(St, Path)
    ).

path_elt(St, Path) -->
    path_primary(St, P),
    (   tok(punct(?))
    ->  { Path = opt(P) }
    ;   tok(punct(*))
    ->  { Path = star(P) }
    ;   tok(punct(+))
    ->  { Path = plus(P) }
    ;   { Path = P }
    ).

path_primary(St, Path) -->
    (   iri(St, IRI)
    ->  { Path = link(IRI) }
    ;   tok(word(a, a))
    ->  { rdf_equal(rdf:type, Type),
          Path = link(Type)
        }
    ;   tok(punct(!))
    ->  negated_set(St, Path)
    ;   tok(punct('('))
    ->  path(St, Path),
        tok(punct(')'))
    ).

negated_set(St, nps(Fwd, Bwd)) -->
    (   tok(punct('('))
    ->  (   tok(punct(')'))
        ->  { Items = [] }
        ;   negated_one(St, I),
            negated_more(St, Is),
            tok(punct(')')),
            { Items = [I|Is] }
        )
    ;   negated_one(St, I),
        { Items = [I] }
    ),
    { findall(P, member(fwd(P), Items), Fwd0),
      findall(P, member(bwd(P), Items), Bwd0),
      (   Fwd0 == [], Bwd0 \== []
      ->  Fwd = none
      ;   Fwd = Fwd0
      ),
      (   Bwd0 == []
      ->  Bwd = none
      ;   Bwd = Bwd0
      )
    }.

negated_more(St, [I|Is]) -->
    tok(punct('|')),
    !,
    negated_one(St, I),
    negated_more(St, Is).
negated_more(_, []) --> [].

negated_one(St, Item) -->
    (   tok(punct(^))
    ->  negated_iri(St, P),
        { Item = bwd(P) }
    ;   negated_iri(St, P),
        { Item = fwd(P) }
    ).

negated_iri(St, P) -->
    (   iri(St, P)
    ->  []
    ;   tok(word(a, a)),
        { rdf_equal(rdf:type, P) }
    ).

%   normalize_path(+Path, -Normal): inverses pushed down to links.

normalize_path(link(P), link(P)).
normalize_path(inv(P), N) :-
    invert_path(P, N).
normalize_path(seq(A, B), seq(NA, NB)) :-
    normalize_path(A, NA),
    normalize_path(B, NB).
normalize_path(alt(A, B), alt(NA, NB)) :-
    normalize_path(A, NA),
    normalize_path(B, NB).
normalize_path(star(A), star(NA)) :-
    normalize_path(A, NA).
normalize_path(plus(A), plus(NA)) :-
    normalize_path(A, NA).
normalize_path(opt(A), opt(NA)) :-
    normalize_path(A, NA).
normalize_path(nps(F, B), nps(F, B)).

invert_path(link(P), inv(link(P))).
invert_path(inv(P), N) :-
    normalize_path(P, N).
invert_path(seq(A, B), seq(NB, NA)) :-
    invert_path(A, NA),
    invert_path(B, NB).
invert_path(alt(A, B), alt(NA, NB)) :-
    invert_path(A, NA),
    invert_path(B, NB).
invert_path(star(A), star(NA)) :-
    invert_path(A, NA).
invert_path(plus(A), plus(NA)) :-
    invert_path(A, NA).
invert_path(opt(A), opt(NA)) :-
    invert_path(A, NA).
invert_path(nps(F, B), nps(B, F)).

%   path_triples(+St, +S, +Path, +O, -Triples): SPARQL 1.1 §18.2.2.4:
%   links become triples, sequences introduce hidden variables, other
%   paths stay path(S, Path, O).

path_triples(_, S, link(P), O, [rdf(S, P, O)]) :- !.
path_triples(_, S, inv(link(P)), O, [rdf(O, P, S)]) :- !.
path_triples(St, S, seq(A, B), O, Triples) :-
    !,
    fresh_variable(St, V),
    path_triples(St, S, A, V, T1),
    path_triples(St, V, B, O, T2),
    append(T1, T2, Triples).
path_triples(_, S, Path, O, [path(S, Path, O)]).

		 /*******************************
		 *    PARSING: TERMS, VALUES    *
		 *******************************/

iri(St, IRI) -->
    (   tokp(iri(Rel), P)
    ->  { resolve_iri(St, Rel, P, IRI) }
    ;   tokp(pname(Prefix, Local), P)
    ->  { St = st(Prefixes, _, _, _),
          (   memberchk(Prefix-NS, Prefixes)
          ->  atom_concat(NS, Local, IRI)
          ;   semantic_error("Unresolved prefixed name: ~w:~w",
                             [Prefix, Local], P)
          )
        }
    ).

%   resolve_iri(+St, +Text, +Pos, -IRI): absolute IRIs are kept;
%   relative ones are resolved against BASE, or, without BASE, taken
%   as names in the default namespace (as ORO names are).

resolve_iri(St, Text, _, IRI) :-
    (   uri_is_global(Text)
    ->  IRI = Text
    ;   St = st(_, Base, _, _),
        Base \== none
    ->  uri_resolve(Text, Base, IRI)
    ;   oro_default_namespace(NS),
        atom_concat(NS, Text, IRI)
    ).

rdf_literal(St, T) -->
    tok(str(S)),
    (   tok(langtag(L))
    ->  { T = literal(lang(L, S)) }
    ;   tok(punct('^^'))
    ->  iri(St, Type),
        { T = literal(type(Type, S)) }
    ;   { T = literal(S) }
    ).

numeric_literal(T) -->
    (   tok(punct(-))
    ->  { Sign = '-' }
    ;   tok(punct(+))
    ->  { Sign = '' }
    ;   { Sign = '' }
    ),
    tok(num(Kind, Lex0)),
    { atom_concat(Sign, Lex0, Lex),
      kind_type(Kind, Type),
      T = literal(type(Type, Lex))
    }.

boolean_literal(literal(type(T, B))) -->
    tok(word(B, _)),
    { memberchk(B, [true, false]),
      rdf_equal(xsd:boolean, T)
    }.

data_block(St, values(Vars, Rows)) -->
    (   tok(var(N))
    ->  { Vars = [N] },
        tok(punct('{')),
        data_values(St, Values),
        tok(punct('}')),
        { findall(Row, ( member(V, Values), value_row([N], [V], Row) ), Rows) }
    ;   tok(punct('(')),
        data_vars(Vars),
        tok(punct(')')),
        tok(punct('{')),
        data_rows(St, Vars, Rows),
        tok(punct('}'))
    ).

data_vars([N|Ns]) --> tok(var(N)), !, data_vars(Ns).
data_vars([]) --> [].

data_rows(St, Vars, [Row|Rows]) -->
    tokp(punct('('), P),
    !,
    data_values(St, Values),
    tok(punct(')')),
    { length(Vars, NV),
      length(Values, NX),
      (   NV =:= NX
      ->  value_row(Vars, Values, Row)
      ;   semantic_error("VALUES: ~d values for ~d variables", [NX, NV], P)
      )
    },
    data_rows(St, Vars, Rows).
data_rows(_, _, []) --> [].

data_values(St, [V|Vs]) -->
    data_value(St, V),
    !,
    data_values(St, Vs).
data_values(_, []) --> [].

data_value(St, V) -->
    (   iri(St, V)
    ->  []
    ;   rdf_literal(St, V)
    ->  []
    ;   numeric_literal(V)
    ->  []
    ;   boolean_literal(V)
    ->  []
    ;   kw(undef)
    ->  { V = '$undef' }
    ).

value_row(Vars, Values, Row) :-
    pairs_keys_values(Pairs, Vars, Values),
    exclude(undef_pair, Pairs, Pairs1),
    sort(1, @<, Pairs1, Row).

undef_pair(_-'$undef').

		 /*******************************
		 *    PARSING: EXPRESSIONS      *
		 *******************************/

%   Expressions: var(N), const(Term), or/2, and/2, not/1, cmp(Op,A,B),
%   in(E, List), not_in(E, List), add/2, sub/2, mul/2, divide/2,
%   neg/1, pos/1, fn(Name, Args), bound(N), exists(P), not_exists(P),
%   agg(Name, Distinct, Arg, Separator).

constraint(St, E) -->
    (   peek_punct('(')
    ->  bracketted_expression(St, E)
    ;   function_constraint(St, E)
    ).

function_constraint(St, E) -->
    (   builtin_call(St, E)
    ->  []
    ;   iri_function(St, E)
    ).

bracketted_expression(St, E) -->
    tok(punct('(')),
    expression(St, E),
    tok(punct(')')).

expression(St, E) -->
    and_expression(St, E0),
    or_rest(St, E0, E).

or_rest(St, E0, E) -->
    (   tok(punct('||'))
    ->  and_expression(St, E1),
        or_rest(St, or(E0, E1), E)
    ;   { E = E0 }
    ).

and_expression(St, E) -->
    relational_expression(St, E0),
    and_rest(St, E0, E).

and_rest(St, E0, E) -->
    (   tok(punct('&&'))
    ->  relational_expression(St, E1),
        and_rest(St, and(E0, E1), E)
    ;   { E = E0 }
    ).

relational_expression(St, E) -->
    additive_expression(St, A),
    (   relational_operator(Op)
    ->  additive_expression(St, B),
        { E = cmp(Op, A, B) }
    ;   kw(in)
    ->  expression_list(St, L),
        { E = in(A, L) }
    ;   kw(not)
    ->  kw(in),
        expression_list(St, L),
        { E = not_in(A, L) }
    ;   { E = A }
    ).

relational_operator(Op) -->
    { member(Op, [=, '!=', <, >, '<=', '>=']) },
    tok(punct(Op)),
    !.

additive_expression(St, E) -->
    multiplicative_expression(St, E0),
    additive_rest(St, E0, E).

additive_rest(St, E0, E) -->
    (   tok(punct(+))
    ->  multiplicative_expression(St, E1),
        additive_rest(St, add(E0, E1), E)
    ;   tok(punct(-))
    ->  multiplicative_expression(St, E1),
        additive_rest(St, sub(E0, E1), E)
    ;   { E = E0 }
    ).

multiplicative_expression(St, E) -->
    unary_expression(St, E0),
    multiplicative_rest(St, E0, E).

multiplicative_rest(St, E0, E) -->
    (   tok(punct(*))
    ->  unary_expression(St, E1),
        multiplicative_rest(St, mul(E0, E1), E)
    ;   tok(punct(/))
    ->  unary_expression(St, E1),
        multiplicative_rest(St, divide(E0, E1), E)
    ;   { E = E0 }
    ).

unary_expression(St, E) -->
    (   tok(punct(!))
    ->  primary_expression(St, E0),
        { E = not(E0) }
    ;   tok(punct(+))
    ->  primary_expression(St, E0),
        { E = pos(E0) }
    ;   tok(punct(-))
    ->  primary_expression(St, E0),
        { E = neg(E0) }
    ;   primary_expression(St, E)
    ).

primary_expression(St, E) -->
    (   tok(punct('('))
    ->  expression(St, E),
        tok(punct(')'))
    ;   tok(var(N))
    ->  { E = var(N) }
    ;   rdf_literal(St, T)
    ->  { E = const(T) }
    ;   tok(num(Kind, Lex))
    ->  { kind_type(Kind, Type),
          E = const(literal(type(Type, Lex)))
        }
    ;   boolean_literal(T)
    ->  { E = const(T) }
    ;   builtin_call(St, E)
    ->  []
    ;   iri_or_function(St, E)
    ).

expression_list(St, L) -->
    tok(punct('(')),
    (   tok(punct(')'))
    ->  { L = [] }
    ;   expression(St, E),
        expression_list_rest(St, Es),
        tok(punct(')')),
        { L = [E|Es] }
    ).

expression_list_rest(St, [E|Es]) -->
    tok(punct(',')),
    !,
    expression(St, E),
    expression_list_rest(St, Es).
expression_list_rest(_, []) --> [].

iri_or_function(St, E) -->
    here(P),
    iri(St, IRI),
    (   peek_punct('(')
    ->  expression_list(St, Args),
        { function_iri(IRI, Args, P, E) }
    ;   { E = const(IRI) }
    ).

iri_function(St, E) -->
    here(P),
    iri(St, IRI),
    expression_list(St, Args),
    { function_iri(IRI, Args, P, E) }.

function_iri(IRI, Args, P, E) :-
    (   cast_type(IRI, Kind)
    ->  (   Args = [A]
        ->  E = fn(cast(Kind), [A])
        ;   oro_iri_name(IRI, Name),
            semantic_error("~w takes one argument", [Name], P)
        )
    ;   semantic_error("Unknown function <~w>", [IRI], P)
    ).

%   Built-in calls: a keyword followed by its arguments.

builtin_call(St, E) -->
    tokp(word(Name, Word), P),
    builtin(Name, Word, P, St, E).

builtin(exists, _, _, St, exists(P)) -->
    !,
    group_graph_pattern(St, P).
builtin(not, _, _, St, not_exists(P)) -->
    !,
    kw(exists),
    group_graph_pattern(St, P).
builtin(bound, _, _, _, bound(N)) -->
    !,
    tok(punct('(')),
    tok(var(N)),
    tok(punct(')')).
builtin(Name, Word, P, St, agg(Name, Distinct, Arg, Sep)) -->
    { aggregate_name(Name) },
    !,
    { (   St = st(_, _, _, aggregates)
      ->  true
      ;   upcase_atom(Word, Up),
          semantic_error("Aggregate ~w is not allowed here", [Up], P)
      ),
      no_aggregates(St, St1)
    },
    tok(punct('(')),
    (   kw(distinct)
    ->  { Distinct = distinct }
    ;   { Distinct = all }
    ),
    (   { Name == count },
        tok(punct(*))
    ->  { Arg = star }
    ;   expression(St1, Arg)
    ),
    (   { Name == group_concat },
        tok(punct(;))
    ->  kw(separator),
        tok(punct(=)),
        tok(str(Sep))
    ;   { Sep = ' ' }
    ),
    tok(punct(')')).
builtin(Name, Word, P, St, fn(Name, Args)) -->
    { function_arity(Name, Min, Max) },
    !,
    expression_list(St, Args),
    { length(Args, N),
      (   N >= Min,
          ( Max == inf -> true ; N =< Max )
      ->  true
      ;   upcase_atom(Word, Up),
          semantic_error("Wrong number of arguments (~d) for ~w", [N, Up], P)
      )
    }.
builtin(Name, Word, P, _, _) -->
    peek_punct('('),
    { \+ keyword(Name),
      upcase_atom(Word, Up),
      semantic_error("Unknown or unsupported function ~w", [Up], P)
    }.

keyword(Name) :-
    memberchk(Name, [ select, ask, construct, describe, where, from, named,
                      prefix, base, distinct, reduced, group, by, having,
                      order, asc, desc, limit, offset, values, optional,
                      filter, union, minus, bind, as, graph, service, undef,
                      in, not, exists, separator, a, true, false
                    ]).

aggregate_name(count).
aggregate_name(sum).
aggregate_name(min).
aggregate_name(max).
aggregate_name(avg).
aggregate_name(sample).
aggregate_name(group_concat).

%   function_arity(?Name, ?Min, ?Max)

function_arity(str, 1, 1).
function_arity(lang, 1, 1).
function_arity(langmatches, 2, 2).
function_arity(datatype, 1, 1).
function_arity(iri, 1, 1).
function_arity(uri, 1, 1).
function_arity(isiri, 1, 1).
function_arity(isuri, 1, 1).
function_arity(isblank, 1, 1).
function_arity(isliteral, 1, 1).
function_arity(isnumeric, 1, 1).
function_arity(regex, 2, 3).
function_arity(replace, 3, 4).
function_arity(contains, 2, 2).
function_arity(strstarts, 2, 2).
function_arity(strends, 2, 2).
function_arity(strbefore, 2, 2).
function_arity(strafter, 2, 2).
function_arity(strlen, 1, 1).
function_arity(substr, 2, 3).
function_arity(ucase, 1, 1).
function_arity(lcase, 1, 1).
function_arity(concat, 0, inf).
function_arity(encode_for_uri, 1, 1).
function_arity(strlang, 2, 2).
function_arity(strdt, 2, 2).
function_arity(abs, 1, 1).
function_arity(ceil, 1, 1).
function_arity(floor, 1, 1).
function_arity(round, 1, 1).
function_arity(if, 3, 3).
function_arity(coalesce, 0, inf).
function_arity(sameterm, 2, 2).

		 /*******************************
		 *           DATATYPES          *
		 *******************************/

kind_type(integer, xsd:integer).
kind_type(decimal, xsd:decimal).
kind_type(float,   xsd:float).
kind_type(double,  xsd:double).

date_type(xsd:dateTime).
date_type(xsd:date).

cast_type(xsd:string, string).
cast_type(xsd:integer, integer).
cast_type(xsd:decimal, decimal).
cast_type(xsd:float, float).
cast_type(xsd:double, double).
cast_type(xsd:boolean, boolean).

type_literal(Type, Lex, literal(type(Type, Lex))).

kind_rank(integer, 0).
kind_rank(decimal, 1).
kind_rank(float, 2).
kind_rank(double, 3).

		 /*******************************
		 *          ANNOTATION          *
		 *******************************/

%   Before evaluation each pattern P becomes p(Certain, Op), Certain
%   the ordered set of the variables bound in every solution of P, and
%   every basic graph pattern a template of Prolog variables.

annotate_query(select(Proj0, D, P0, Mods0), select(Proj, D, P, Mods)) :-
    annotate(P0, P),
    maplist(annotate_item, Proj0, Proj),
    annotate_expr(Mods0, Mods).
annotate_query(ask(P0, Mods0), ask(P, Mods)) :-
    annotate(P0, P),
    annotate_expr(Mods0, Mods).

annotate_item(var(N), var(N)).
annotate_item(as(E0, N), as(E, N)) :-
    annotate_expr(E0, E).

annotate(bgp(Ts), p(Names, bgp(Id, Names, Template))) :-
    flag(oro_sparql_bgp, Id, Id + 1),
    bgp_template(Ts, Names, Template).
annotate(join(A0, B0), p(C, join(A, B))) :-
    annotate(A0, A), annotate(B0, B),
    A = p(CA, _), B = p(CB, _),
    ord_union(CA, CB, C).
annotate(union(A0, B0), p(C, union(A, B))) :-
    annotate(A0, A), annotate(B0, B),
    A = p(CA, _), B = p(CB, _),
    ord_intersection(CA, CB, C).
annotate(left_join(A0, B0, E0), p(C, left_join(A, B, E))) :-
    annotate(A0, A), annotate(B0, B),
    A = p(C, _),
    annotate_expr(E0, E).
annotate(minus(A0, B0), p(C, minus(A, B))) :-
    annotate(A0, A), annotate(B0, B),
    A = p(C, _).
annotate(filter(E0, A0), P) :-
    annotate(A0, A),
    annotate_expr(E0, E),
    push_filter(E, A, P).
annotate(extend(A0, N, E0), p(C, extend(A, N, E))) :-
    annotate(A0, A),
    A = p(C, _),
    annotate_expr(E0, E).
annotate(values(Vars, Rows), p(C, values(Rows))) :-
    sort(Vars, Sorted),
    include(bound_in_all(Rows), Sorted, C).
annotate(subselect(Q0), p([], subselect(Q, cache(none)))) :-
    annotate_query(Q0, Q).

%   push_filter(+Expr, +Annotated, -Pattern): the conjuncts of a FILTER
%   over a basic graph pattern whose variables the pattern binds become
%   test goals of the pattern, run as soon as their variables are bound
%   (FILTER(A && B) is FILTER(A) FILTER(B), and a conjunct only reads
%   variables every solution binds, so testing it early changes
%   nothing but the work).  Conjuncts with EXISTS stay outside.

push_filter(E, A, P) :-
    A = p(C, Op),
    (   Op = bgp(Id, Names, t(PVars, Goals))
    ->  conjuncts(E, Es),
        partition(pushable(Names), Es, Push, Keep),
        pairs_keys_values(Map, Names, PVars),
        maplist(test_goal(Map), Push, Tests),
        append(Goals, Tests, Goals1),
        A1 = p(C, bgp(Id, Names, t(PVars, Goals1))),
        (   Keep == []
        ->  P = A1
        ;   conjunction(Keep, K),
            P = p(C, filter(K, A1))
        )
    ;   P = p(C, filter(E, A))
    ).

conjuncts(and(A, B), Es) :-
    !,
    conjuncts(A, EA),
    conjuncts(B, EB),
    append(EA, EB, Es).
conjuncts(E, [E]).

pushable(Names, E) :-
    \+ ( sub_term(X, E),
          compound(X),
          ( X = exists(_) ; X = not_exists(_) ; X = agg(_, _, _, _) )
        ),
    free_variables(E, Vars),
    ord_subset(Vars, Names).

test_goal(Map, E, test(E, Pairs)) :-
    free_variables(E, Vars),
    maplist(variable_pair(Map), Vars, Pairs).

variable_pair(Map, N, N-V) :-
    memberchk(N-V, Map).

bound_in_all(Rows, N) :-
    forall(member(Row, Rows), memberchk(N-_, Row)).

annotate_expr(exists(P0), exists(P)) :-
    !,
    annotate(P0, P).
annotate_expr(not_exists(P0), not_exists(P)) :-
    !,
    annotate(P0, P).
annotate_expr(const(T), const(T)) :-
    !.
annotate_expr(E0, E) :-
    compound(E0),
    !,
    E0 =.. [F|Args0],
    maplist(annotate_expr, Args0, Args),
    E1 =.. [F|Args],
    fold_constant(E1, E).
annotate_expr(E, E).

%   fold_constant(+E0, -E): an operator or function applied to constants
%   is evaluated once (if that raises an expression error it is left
%   for evaluation time, where it belongs to a solution).

fold_constant(E0, E) :-
    foldable(E0),
    E0 =.. [_|Args],
    forall(member(A, Args), constant_argument(A)),
    empty_assoc(Empty),
    eval_expr(E0, [], ctx(none, [], none, cache(Empty)), V),
    !,
    E = const(V).
fold_constant(E, E).

foldable(fn(Name, _)) :-
    \+ memberchk(Name, [if, coalesce]).
foldable(cmp(_, _, _)).
foldable(add(_, _)).
foldable(sub(_, _)).
foldable(mul(_, _)).
foldable(divide(_, _)).
foldable(neg(_)).
foldable(pos(_)).
foldable(not(_)).

constant_argument(const(_)) :- !.
constant_argument(Name) :- atom(Name), !.
constant_argument(cast(_)) :- !.
constant_argument(Args) :-
    is_list(Args),
    forall(member(A, Args), A = const(_)).

%   bgp_template(+Triples, -Names, -Template): Template is
%   t(Vars, Goals), Vars the Prolog variables standing for Names.

bgp_template(Ts, Names, t(PVars, Goals)) :-
    phrase(triples_variables(Ts), Names0),
    sort(Names0, Names),
    length(Names, N),
    length(PVars, N),
    pairs_keys_values(Map, Names, PVars),
    maplist(goal_template(Map), Ts, Goals).

triples_variables([]) --> [].
triples_variables([T|Ts]) -->
    { T =.. [_, S, P, O] },
    node_variable(S), node_variable(P), node_variable(O),
    triples_variables(Ts).

node_variable(var(N)) --> !, [N].
node_variable(_) --> [].

goal_template(Map, rdf(S0, P0, O0), rdf(S, P, O)) :-
    maplist(node_template(Map), [S0, P0, O0], [S, P, O]).
goal_template(Map, path(S0, Path, O0), path(S, Path, O)) :-
    node_template(Map, S0, S),
    node_template(Map, O0, O).

node_template(Map, var(N), V) :-
    !,
    memberchk(N-V, Map).
node_template(_, T, T).

		 /*******************************
		 *         QUERY RUNNER         *
		 *******************************/

%   The evaluation context: ctx(Model, Subst, Group, Cache), Subst the
%   bindings EXISTS substitutes (Name-Value, sorted), Group the member
%   solutions of the current group (or `none`), Cache a mutable
%   cache(Assoc) of cost estimates.

run_query(Model, Query0, Result) :-
    annotate_query(Query0, Query),
    empty_assoc(Empty),
    Ctx = ctx(Model, [], none, cache(Empty)),
    query_result(Query, Ctx, Result).

query_result(select(Proj, D, P, Mods), Ctx, select(Vars, Rows)) :-
    projection_names(Proj, Vars),
    select_rows(select(Proj, D, P, Mods), Ctx, Rows).
query_result(ask(P, mods(A, G, H, O, Off, Lim0, V)), Ctx, ask(Bool)) :-
    Lim is min(Lim0, 1),
    select_rows(select([], all, P, mods(A, G, H, O, Off, Lim, V)), Ctx, Rows),
    (   Rows == []
    ->  Bool = false
    ;   Bool = true
    ).

projection_names(Proj, Vars) :-
    maplist(projection_name, Proj, Vars).

projection_name(var(N), N).
projection_name(as(_, N), N).

%   select_rows(+Query, +Ctx, -Rows): the projected rows, each a list
%   of Name-Value in projection order.

select_rows(select(Proj, Distinct, P, Mods), Ctx, Rows) :-
    Mods = mods(Agg, Group, Having, Order, Offset, Limit, Values),
    projection_names(Proj, Vars),
    (   Agg == false,
        Order == []
    ->  Goal = ( eval(P, Ctx, [], Mu0),
                 join_values(Values, Mu0, Mu1),
                 extend_projection(Proj, Ctx, Mu1, Mu),
                 project(Vars, Mu, Row)
               ),
        (   Distinct == distinct
        ->  Goal1 = distinct(Row, Goal)
        ;   Goal1 = Goal
        ),
        slice(Offset, Limit, Goal1, Goal2),
        findall(Row, Goal2, Rows)
    ;   findall(Mu, eval(P, Ctx, [], Mu), Solutions),
        (   Agg == true
        ->  group_rows(Group, Solutions, Ctx, Rows0),
            include(having(Having, Ctx), Rows0, Rows1)
        ;   findall(row(Mu, none), member(Mu, Solutions), Rows1)
        ),
        findall(row(Mu, G), ( member(row(Mu0, G), Rows1),
                              join_values(Values, Mu0, Mu)
                            ), Rows2),
        maplist(extend_row(Proj, Ctx), Rows2, Rows3),
        order_rows(Order, Ctx, Rows3, Rows4),
        findall(Row, ( member(row(Mu, _), Rows4), project(Vars, Mu, Row) ),
                Rows5),
        (   Distinct == distinct
        ->  list_to_set(Rows5, Rows6)
        ;   Rows6 = Rows5
        ),
        slice_list(Offset, Limit, Rows6, Rows)
    ).

slice(0, inf, Goal, Goal) :- !.
slice(0, Limit, Goal, limit(Limit, Goal)) :- !.
slice(Offset, inf, Goal, offset(Offset, Goal)) :- !.
slice(Offset, Limit, Goal, limit(Limit, offset(Offset, Goal))).

slice_list(Offset, Limit, List, Slice) :-
    length(List, Len),
    (   Offset >= Len
    ->  Slice = []
    ;   length(Skip, Offset),
        append(Skip, Rest, List),
        (   Limit == inf
        ->  Slice = Rest
        ;   length(Rest, RLen),
            (   Limit >= RLen
            ->  Slice = Rest
            ;   length(Slice, Limit),
                append(Slice, _, Rest)
            )
        )
    ).

join_values(none, Mu, Mu) :- !.
join_values(values(_, Rows), Mu0, Mu) :-
    member(Row, Rows),
    merge_solutions(Mu0, Row, Mu).

extend_projection([], _, Mu, Mu).
extend_projection([Item|Items], Ctx, Mu0, Mu) :-
    (   Item = as(E, N)
    ->  (   eval_expr(E, Mu0, Ctx, V)
        ->  put_binding(N, V, Mu0, Mu1)
        ;   Mu1 = Mu0
        )
    ;   Mu1 = Mu0
    ),
    extend_projection(Items, Ctx, Mu1, Mu).

extend_row(Proj, Ctx0, row(Mu0, G), row(Mu, G)) :-
    group_context(Ctx0, G, Ctx),
    extend_projection(Proj, Ctx, Mu0, Mu).

project(Vars, Mu, Row) :-
    project_(Vars, Mu, Row).

project_([], _, []).
project_([N|Ns], Mu, Row) :-
    (   memberchk(N-V, Mu)
    ->  Row = [N-V|Row1]
    ;   Row = Row1
    ),
    project_(Ns, Mu, Row1).

group_context(ctx(M, S, _, C), none, ctx(M, S, none, C)) :- !.
group_context(ctx(M, S, _, C), G, ctx(M, S, G, C)).

having(Having, Ctx0, row(Mu, G)) :-
    group_context(Ctx0, G, Ctx),
    forall(member(E, Having), expr_true(E, Mu, Ctx)).

%   Grouping: rows row(KeyBindings, Members).

group_rows(none, Solutions, _, [row([], Solutions)]) :- !.
group_rows(Keys, Solutions, Ctx, Rows) :-
    map_list_to_pairs(group_key(Keys, Ctx), Solutions, Keyed),
    keysort(Keyed, Sorted),
    group_pairs_by_key(Sorted, Groups),
    findall(row(KeyMu, Members),
            ( member(Key-Members, Groups),
              key_bindings(Keys, Key, KeyMu0),
              sort(1, @<, KeyMu0, KeyMu)
            ),
            Rows).

group_key(Keys, Ctx, Mu, Key) :-
    maplist(key_value(Ctx, Mu), Keys, Key).

key_value(Ctx, Mu, key(E, _), V) :-
    (   eval_expr(E, Mu, Ctx, V0)
    ->  V = V0
    ;   V = '$unbound'
    ).

key_bindings([], [], []).
key_bindings([key(E, As)|Keys], [V|Vs], Bindings) :-
    (   V == '$unbound'
    ->  Bindings = Bindings1
    ;   As \== none
    ->  Bindings = [As-V|Bindings1]
    ;   E = var(N)
    ->  Bindings = [N-V|Bindings1]
    ;   Bindings = Bindings1
    ),
    key_bindings(Keys, Vs, Bindings1).

%   ORDER BY

order_rows([], _, Rows, Rows) :- !.
order_rows(Order, Ctx, Rows, Sorted) :-
    findall(k(Keys, I)-Row,
            ( nth1(I, Rows, Row),
              Row = row(Mu, G),
              group_context(Ctx, G, CtxG),
              maplist(order_key(Mu, CtxG), Order, Keys)
            ),
            Keyed),
    predsort(compare_order(Order), Keyed, SortedKeyed),
    pairs_values(SortedKeyed, Sorted).

order_key(Mu, Ctx, Cond, V) :-
    arg(1, Cond, E),
    (   eval_expr(E, Mu, Ctx, V0)
    ->  V = V0
    ;   V = '$unbound'
    ).

compare_order(Conds, Order, k(K1, I1)-_, k(K2, I2)-_) :-
    compare_keys(Conds, K1, K2, O),
    (   O == (=)
    ->  compare(Order, I1, I2)
    ;   Order = O
    ).

compare_keys([], [], [], =).
compare_keys([C|Cs], [A|As], [B|Bs], Order) :-
    term_order(A, B, O0),
    (   functor(C, desc, 1)
    ->  flip_order(O0, O)
    ;   O = O0
    ),
    (   O == (=)
    ->  compare_keys(Cs, As, Bs, Order)
    ;   Order = O
    ).

flip_order(<, >).
flip_order(>, <).
flip_order(=, =).

%   term_order(+A, +B, -Order): the ORDER BY order: unbound < blank
%   nodes < IRIs < literals; literals by value when comparable.

term_order(A, B, Order) :-
    term_rank(A, RA),
    term_rank(B, RB),
    (   RA =\= RB
    ->  compare(Order, RA, RB)
    ;   RA =:= 3,
        value_class(A, CA),
        value_class(B, CB),
        order_class(CA, CB, O0),
        O0 \== (=)
    ->  Order = O0
    ;   compare(Order, A, B)
    ).

term_rank('$unbound', 0) :- !.
term_rank(literal(_), 3) :- !.
term_rank(X, 1) :- rdf_is_bnode(X), !.
term_rank(_, 2).

		 /*******************************
		 *      PATTERN EVALUATION      *
		 *******************************/

%   eval(+P, +Ctx, +Mu0, -Mu): Mu is a solution of Join({Mu0}, P).
%   Only the certain variables of P are pushed into it.

eval(p(Certain, Op), Ctx, Mu0, Mu) :-
    restrict(Mu0, Certain, In),
    solve(Op, Ctx, In, Mu1),
    merge_solutions(Mu0, Mu1, Mu).

%   solve(+Op, +Ctx, +In, -Mu): Mu is a solution of the pattern Op
%   compatible with In, whose variables Op is certain to bind.

solve(bgp(Id, Names, Template), Ctx, In, Mu) :-
    solve_bgp(Id, Names, Template, Ctx, In, Mu).
solve(join(A, B), Ctx, In, Mu) :-
    eval(A, Ctx, In, Mu1),
    eval(B, Ctx, Mu1, Mu).
solve(union(A, B), Ctx, In, Mu) :-
    (   eval(A, Ctx, In, Mu)
    ;   eval(B, Ctx, In, Mu)
    ).
solve(filter(E, p(_, Op)), Ctx, In, Mu) :-
    solve(Op, Ctx, In, Mu),
    expr_true(E, Mu, Ctx).
solve(left_join(p(_, A), B, E), Ctx, In, Mu) :-
    solve(A, Ctx, In, Mu1),
    findall(Mu2, ( eval(B, Ctx, Mu1, Mu2),
                   expr_true(E, Mu2, Ctx)
                 ), Extensions),
    (   Extensions == []
    ->  Mu = Mu1
    ;   member(Mu, Extensions)
    ).
solve(minus(p(_, A), p(CB, B)), Ctx, In, Mu) :-
    solve(A, Ctx, In, Mu),
    restrict(Mu, CB, InB),
    \+ ( solve(B, Ctx, InB, MuB),
         compatible(Mu, MuB),
         shares_variable(Mu, MuB)
       ).
solve(extend(p(_, A), N, E), Ctx, In, Mu) :-
    solve(A, Ctx, In, Mu1),
    (   eval_expr(E, Mu1, Ctx, V)
    ->  put_binding(N, V, Mu1, Mu)
    ;   Mu = Mu1
    ).
solve(values(Rows), _, In, Mu) :-
    member(Mu, Rows),
    compatible(In, Mu).
solve(subselect(Query, Cache), Ctx, In, Mu) :-
    subselect_rows(Query, Cache, Ctx, Rows),
    member(Row, Rows),
    sort(1, @<, Row, Mu),
    compatible(In, Mu).

subselect_rows(Query, Cache, Ctx, Rows) :-
    Ctx = ctx(_, Subst, _, _),
    (   Subst == [],
        arg(1, Cache, rows(Rows0))
    ->  Rows = Rows0
    ;   Query = select(Proj, D, P, Mods),
        group_context(Ctx, none, Ctx1),
        select_rows(select(Proj, D, P, Mods), Ctx1, Rows),
        (   Subst == []
        ->  nb_setarg(1, Cache, rows(Rows))
        ;   true
        )
    ).

%   Solution mappings: lists of Name-Value sorted by Name.

restrict([], _, []) :- !.
restrict(_, [], []) :- !.
restrict([N-V|Mu], [C|Cs], In) :-
    compare(Order, N, C),
    (   Order == (=)
    ->  In = [N-V|In1],
        restrict(Mu, Cs, In1)
    ;   Order == (<)
    ->  restrict(Mu, [C|Cs], In)
    ;   restrict([N-V|Mu], Cs, In)
    ).

merge_solutions([], Mu, Mu) :- !.
merge_solutions(Mu, [], Mu) :- !.
merge_solutions([N1-V1|T1], [N2-V2|T2], Mu) :-
    compare(Order, N1, N2),
    (   Order == (=)
    ->  V1 == V2,
        Mu = [N1-V1|Mu1],
        merge_solutions(T1, T2, Mu1)
    ;   Order == (<)
    ->  Mu = [N1-V1|Mu1],
        merge_solutions(T1, [N2-V2|T2], Mu1)
    ;   Mu = [N2-V2|Mu1],
        merge_solutions([N1-V1|T1], T2, Mu1)
    ).

compatible(Mu1, Mu2) :-
    \+ ( member(N-V1, Mu1),
         memberchk(N-V2, Mu2),
         V1 \== V2
       ).

shares_variable(Mu1, Mu2) :-
    member(N-_, Mu1),
    memberchk(N-_, Mu2),
    !.

put_binding(N, V, Mu0, Mu) :-
    (   memberchk(N-V0, Mu0)
    ->  V0 == V,
        Mu = Mu0
    ;   merge_solutions(Mu0, [N-V], Mu)
    ).

lookup(N, Mu, ctx(_, Subst, _, _), V) :-
    (   memberchk(N-V0, Mu)
    ->  V = V0
    ;   memberchk(N-V0, Subst)
    ->  V = V0
    ).

		 /*******************************
		 *     BASIC GRAPH PATTERNS     *
		 *******************************/

%   solve_bgp(+Id, +Names, +Template, +Ctx, +In, -Mu): the goals run in
%   the order of a plan made once per query for each set of variables
%   bound on entry (see plan_goals/5).

solve_bgp(Id, Names, Template, Ctx, In, Mu) :-
    Ctx = ctx(_, Subst, _, _),
    bound_names(Names, In, Subst, Bound),
    memo(plan(Id, Bound), Ctx, Order,
         plan_goals(Template, Names, Bound, Ctx, Order)),
    copy_term(Template, t(PVars, Goals)),
    bind_inputs(Names, PVars, In, Subst),
    order_goals(Order, Goals, Ordered),
    run_goals(Ordered, Ctx),
    pairs_keys_values(Mu, Names, PVars).

bound_names(Names, In, Subst, Bound) :-
    include(bound_name(In, Subst), Names, Bound).

bound_name(In, Subst, N) :-
    (   memberchk(N-_, In)
    ->  true
    ;   memberchk(N-_, Subst)
    ).

bind_inputs([], [], _, _).
bind_inputs([N|Ns], [V|Vs], In, Subst) :-
    (   memberchk(N-X, In)
    ->  V = X
    ;   memberchk(N-X, Subst)
    ->  V = X
    ;   true
    ),
    bind_inputs(Ns, Vs, In, Subst).

order_goals([], _, []).
order_goals([I|Is], Goals, [G|Gs]) :-
    nth1(I, Goals, G),
    order_goals(Is, Goals, Gs).

run_goals([], _).
run_goals([Goal|Goals], Ctx) :-
    run_goal(Goal, Ctx),
    run_goals(Goals, Ctx).

run_goal(rdf(S, P, O), Ctx) :-
    triple(Ctx, S, P, O).
run_goal(path(S, Path, O), Ctx) :-
    path_holds(Path, Ctx, S, O).
run_goal(test(E, Mu), Ctx) :-
    expr_true(E, Mu, Ctx).

triple(ctx(Model, _, _, _), S, P, O) :-
    resource_or_var(S),
    resource_or_var(P),
    oro_holds(Model, S, P, O).

resource_or_var(X) :-
    (   var(X)
    ->  true
    ;   atom(X)
    ).

%   plan_goals(+Template, +Names, +Bound, +Ctx, -Order): Order lists
%   the goals (by position) greedily, always the cheapest given the
%   variables bound so far.  While planning, a bound variable whose
%   value is not known yet is the atom '$bound'; constants of the query
%   are estimated by their actual counts.

plan_goals(Template, Names, Bound, Ctx, Order) :-
    copy_term(Template, t(PVars, Goals)),
    pairs_keys_values(Map, Names, PVars),
    maplist(mark_bound(Map), Bound),
    numbered(Goals, 1, Indexed),
    plan(Indexed, Ctx, Order),
    debug(oro(sparql), 'Plan ~q for ~q bound: ~q', [Order, Bound, Goals]).

numbered([], _, []).
numbered([G|Gs], I, [I-G|IGs]) :-
    I1 is I + 1,
    numbered(Gs, I1, IGs).

mark_bound(Map, N) :-
    memberchk(N-'$bound', Map).

plan([], _, []).
plan(Indexed, Ctx, [I|Order]) :-
    Indexed = [I0-G0|Rest0],
    goal_cost(G0, Ctx, C0),
    cheapest(Rest0, Ctx, I0-G0, C0, I-G),
    delete_index(Indexed, I, Rest),
    term_variables(G, Vars),
    maplist(=('$bound'), Vars),
    plan(Rest, Ctx, Order).

cheapest([], _, Best, _, Best).
cheapest([I-G|Gs], Ctx, Best0, C0, Best) :-
    goal_cost(G, Ctx, C),
    (   C < C0
    ->  cheapest(Gs, Ctx, I-G, C, Best)
    ;   cheapest(Gs, Ctx, Best0, C0, Best)
    ).

delete_index([J-G|T], I, Rest) :-
    (   J == I
    ->  Rest = T
    ;   Rest = [J-G|Rest1],
        delete_index(T, I, Rest1)
    ).

%   goal_cost(+Goal, +Ctx, -Cost): the expected number of solutions of
%   Goal, a part being unbound (a variable), bound to a value not known
%   yet ('$bound') or a constant.

goal_cost(rdf(S, P, O), Ctx, Cost) :-
    (   nonvar(S),
        S = literal(_)
    ->  Cost = 0
    ;   nonvar(S), nonvar(P), nonvar(O)
    ->  check_cost(P, O, Ctx, Cost)
    ;   ( var(P) ; P == '$bound' )
    ->  (   nonvar(S)
        ->  node_estimate(S, subject, N),
            Cost is 10 + N
        ;   nonvar(O)
        ->  node_estimate(O, object, N),
            Cost is 10 + N
        ;   Cost = 1.0e12
        )
    ;   \+ atom(P)
    ->  Cost = 0
    ;   rdf_equal(P, rdf:type)
    ->  (   O == '$bound'
        ->  Cost = 100
        ;   nonvar(O)
        ->  (   atom(O)
            ->  cached_cost(type(O), Ctx, Cost)
            ;   Cost = 0
            )
        ;   nonvar(S)
        ->  Cost = 12
        ;   cached_cost(predicate(P), Ctx, N),
            Cost is 2 * N + 1000
        )
    ;   cached_cost(predicate(P), Ctx, NP),
        (   nonvar(S)
        ->  cached_cost(fan_out(P), Ctx, F),
            (   S == '$bound'
            ->  Cost is 2 + min(NP, F)
            ;   rdf_estimate_complexity(S, _, _, NS),
                Cost is 2 + min(NP, min(F, NS))
            )
        ;   O == '$bound'
        ->  cached_cost(fan_in(P), Ctx, F),
            Cost is 2 + min(NP, F)
        ;   nonvar(O)
        ->  (   O = literal(_)
            ->  Cost is 2 + NP / 10
            ;   rdf_estimate_complexity(_, _, O, NO),
                Cost is min(NP, 2 + NO)
            )
        ;   Cost is NP + 100
        )
    ).
goal_cost(test(_, Pairs), _, Cost) :-
    (   ground(Pairs)
    ->  Cost = 0
    ;   Cost = 1.0e15
    ).
goal_cost(path(S, _, O), _, Cost) :-
    (   nonvar(S), nonvar(O)
    ->  Cost = 20
    ;   ( nonvar(S) ; nonvar(O) )
    ->  Cost = 200
    ;   Cost = 1.0e10
    ).

node_estimate('$bound', _, 20) :- !.
node_estimate(X, Position, N) :-
    (   atom(X)
    ->  (   Position == subject
        ->  rdf_estimate_complexity(X, _, _, N)
        ;   rdf_estimate_complexity(_, _, X, N)
        )
    ;   N = 100
    ).

%   check_cost(+P, +O, +Ctx, -Cost): a triple with all its parts bound
%   is a check.  Checks never add solutions, so they run before any
%   pattern that binds a variable (they cost between 1 and 2), in the
%   order that minimises the expected work: by c/(1-p), c the price of
%   a check (type checks go through the class hierarchy: 4, literal
%   checks compare values: 1.5, others 1) and p the chance it passes
%   (the share of P's triples with this object; 1/2 when the object is
%   not known yet).

check_cost(P, O, Ctx, Cost) :-
    (   P == '$bound'
    ->  Rank = 2
    ;   \+ atom(P)
    ->  Rank = 0
    ;   O = literal(_)
    ->  Rank is 1.5 / 0.5
    ;   rdf_equal(P, rdf:type)
    ->  (   O == '$bound'
        ->  Rank = 8
        ;   cached_cost(type(O), Ctx, NC),
            cached_cost(predicate(P), Ctx, NP),
            Rank is 4 / max(0.01, 1 - NC / (NP + 1))
        )
    ;   O == '$bound'
    ->  Rank = 2
    ;   cached_cost(predicate(P), Ctx, NP),
        rdf_estimate_complexity(_, P, O, NO),
        Rank is 1 / max(0.01, 1 - NO / (NP + 1))
    ),
    Cost is 1 + Rank / (Rank + 1).

%   memo(+Key, +Ctx, -Value, :Goal): Value of Key, computed by Goal once
%   per query.

:- meta_predicate memo(+, +, -, 0).

memo(Key, ctx(_, _, _, Cache), Value, Goal) :-
    arg(1, Cache, Assoc),
    (   get_assoc(Key, Assoc, Value0)
    ->  Value = Value0
    ;   call(Goal),
        arg(1, Cache, Assoc1),
        put_assoc(Key, Assoc1, Value, Assoc2),
        nb_setarg(1, Cache, Assoc2)
    ).

%   cached_cost(+Key, +Ctx, -Cost): estimates that depend on the
%   schema (sub-properties, sub-classes), computed once per query.

cached_cost(Key, ctx(Model, _, _, Cache), Cost) :-
    arg(1, Cache, Assoc),
    (   get_assoc(Key, Assoc, Cost0)
    ->  Cost = Cost0
    ;   estimate(Key, Model, Cost),
        put_assoc(Key, Assoc, Cost, Assoc1),
        nb_setarg(1, Cache, Assoc1)
    ).

estimate(predicate(P), Model, N) :-
    aggregate_all(sum(N0),
                  ( (   Sub = P
                    ;   oro_subproperty(Model, Sub, P),
                        Sub \== P
                    ),
                    rdf_estimate_complexity(_, Sub, _, N0)
                  ),
                  N).
estimate(fan_out(P), Model, F) :-
    aggregate_all(sum(F0),
                  ( (   Sub = P
                    ;   oro_subproperty(Model, Sub, P),
                        Sub \== P
                    ),
                    rdf_current_predicate(Sub),
                    rdf_predicate_property(Sub, rdf_subject_branch_factor(F0))
                  ),
                  F).
estimate(fan_in(P), Model, F) :-
    aggregate_all(sum(F0),
                  ( (   Sub = P
                    ;   oro_subproperty(Model, Sub, P),
                        Sub \== P
                    ),
                    rdf_current_predicate(Sub),
                    rdf_predicate_property(Sub, rdf_object_branch_factor(F0))
                  ),
                  F).
estimate(type(C), Model, N) :-
    rdf_equal(rdf:type, Type),
    (   rdf_equal(C, owl:'Thing')
    ->  rdf_estimate_complexity(_, Type, _, N)
    ;   aggregate_all(sum(N0),
                      ( (   Sub = C
                        ;   oro_subclass(Model, Sub, C),
                            Sub \== C
                        ),
                        rdf_estimate_complexity(_, Type, Sub, N0)
                      ),
                      N)
    ).

		 /*******************************
		 *        PROPERTY PATHS        *
		 *******************************/

%   path_holds(+Path, +Ctx, ?S, ?O): arbitrary-length paths have the
%   distinct-node semantics of SPARQL 1.1 (each end once).  With both
%   ends unbound, the zero-length matches of `*` and `?` are the nodes
%   the path itself touches.

path_holds(link(P), Ctx, S, O) :-
    triple(Ctx, S, P, O).
path_holds(inv(link(P)), Ctx, S, O) :-
    triple(Ctx, O, P, S).
path_holds(seq(A, B), Ctx, S, O) :-
    (   ( nonvar(S) ; var(O) )
    ->  path_holds(A, Ctx, S, M),
        path_holds(B, Ctx, M, O)
    ;   path_holds(B, Ctx, M, O),
        path_holds(A, Ctx, S, M)
    ).
path_holds(alt(A, B), Ctx, S, O) :-
    (   path_holds(A, Ctx, S, O)
    ;   path_holds(B, Ctx, S, O)
    ).
path_holds(nps(Fwd, Bwd), Ctx, S, O) :-
    (   Fwd \== none,
        triple(Ctx, S, P, O),
        \+ memberchk(P, Fwd)
    ;   Bwd \== none,
        triple(Ctx, O, P, S),
        \+ memberchk(P, Bwd)
    ).
path_holds(opt(P), Ctx, S, O) :-
    closure_holds(P, zero_or_one, Ctx, S, O).
path_holds(star(P), Ctx, S, O) :-
    closure_holds(P, zero_or_more, Ctx, S, O).
path_holds(plus(P), Ctx, S, O) :-
    closure_holds(P, one_or_more, Ctx, S, O).

closure_holds(P, How, Ctx, S, O) :-
    (   nonvar(S)
    ->  reached(How, P, fwd, Ctx, S, Set),
        (   nonvar(O)
        ->  memberchk(O, Set)
        ;   member(O, Set)
        )
    ;   nonvar(O)
    ->  reached(How, P, bwd, Ctx, O, Set),
        member(S, Set)
    ;   findall(N, ( path_holds(P, Ctx, X, Y),
                     ( N = X ; N = Y )
                   ), Nodes0),
        sort(Nodes0, Nodes),
        member(S, Nodes),
        reached(How, P, fwd, Ctx, S, Set),
        member(O, Set)
    ).

reached(zero_or_one, P, Dir, Ctx, X, Set) :-
    findall(Y, path_step(Dir, P, Ctx, X, Y), Ys),
    sort([X|Ys], Set).
reached(zero_or_more, P, Dir, Ctx, X, Set) :-
    reach(Dir, P, Ctx, X, Set0),
    ord_union([X], Set0, Set).
reached(one_or_more, P, Dir, Ctx, X, Set) :-
    reach(Dir, P, Ctx, X, Set).

path_step(fwd, P, Ctx, X, Y) :-
    path_holds(P, Ctx, X, Y).
path_step(bwd, P, Ctx, X, Y) :-
    path_holds(P, Ctx, Y, X).

%   reach(+Dir, +P, +Ctx, +X, -Set): the nodes reachable from X in one
%   or more steps of P, breadth first.

reach(Dir, P, Ctx, X, Set) :-
    empty_assoc(Seen0),
    reach_queue([X], Dir, P, Ctx, Seen0, Seen),
    assoc_to_keys(Seen, Set).

reach_queue([], _, _, _, Seen, Seen).
reach_queue([X|Queue], Dir, P, Ctx, Seen0, Seen) :-
    findall(Y, path_step(Dir, P, Ctx, X, Y), Ys0),
    sort(Ys0, Ys),
    foldl(visit, Ys, New, Seen0, Seen1),
    exclude(==(none), New, Fresh),
    append(Queue, Fresh, Queue1),
    reach_queue(Queue1, Dir, P, Ctx, Seen1, Seen).

visit(Y, New, Seen0, Seen) :-
    (   get_assoc(Y, Seen0, _)
    ->  New = none,
        Seen = Seen0
    ;   New = Y,
        put_assoc(Y, Seen0, true, Seen)
    ).

		 /*******************************
		 *          EXPRESSIONS         *
		 *******************************/

%   eval_expr(+Expr, +Mu, +Ctx, -Value) is semidet: failure is an
%   expression error (unbound variable, type error...).

expr_true(E, Mu, Ctx) :-
    eval_expr(E, Mu, Ctx, V),
    ebv(V, true).

eval_expr(var(N), Mu, Ctx, V) :-
    !,
    lookup(N, Mu, Ctx, V).
eval_expr(const(T), _, _, T) :-
    !.
eval_expr(or(A, B), Mu, Ctx, V) :-
    !,
    truth(A, Mu, Ctx, TA),
    (   TA == true
    ->  R = true
    ;   truth(B, Mu, Ctx, TB),
        or3(TA, TB, R)
    ),
    boolean_term(R, V).
eval_expr(and(A, B), Mu, Ctx, V) :-
    !,
    truth(A, Mu, Ctx, TA),
    (   TA == false
    ->  R = false
    ;   truth(B, Mu, Ctx, TB),
        and3(TA, TB, R)
    ),
    boolean_term(R, V).
eval_expr(not(A), Mu, Ctx, V) :-
    !,
    eval_expr(A, Mu, Ctx, VA),
    ebv(VA, B),
    negate(B, R),
    boolean_term(R, V).
eval_expr(cmp(Op, A, B), Mu, Ctx, V) :-
    !,
    eval_expr(A, Mu, Ctx, VA),
    eval_expr(B, Mu, Ctx, VB),
    compare_values(Op, VA, VB, R),
    boolean_term(R, V).
eval_expr(in(A, L), Mu, Ctx, V) :-
    !,
    eval_expr(A, Mu, Ctx, VA),
    membership(L, VA, Mu, Ctx, false, R),
    boolean_term(R, V).
eval_expr(not_in(A, L), Mu, Ctx, V) :-
    !,
    eval_expr(A, Mu, Ctx, VA),
    membership(L, VA, Mu, Ctx, false, R0),
    negate(R0, R),
    boolean_term(R, V).
eval_expr(bound(N), Mu, Ctx, V) :-
    !,
    (   lookup(N, Mu, Ctx, _)
    ->  boolean_term(true, V)
    ;   boolean_term(false, V)
    ).
eval_expr(exists(P), Mu, Ctx, V) :-
    !,
    exists(P, Mu, Ctx, R),
    boolean_term(R, V).
eval_expr(not_exists(P), Mu, Ctx, V) :-
    !,
    exists(P, Mu, Ctx, R0),
    negate(R0, R),
    boolean_term(R, V).
eval_expr(fn(if, [C, A, B]), Mu, Ctx, V) :-
    !,
    eval_expr(C, Mu, Ctx, VC),
    ebv(VC, T),
    (   T == true
    ->  eval_expr(A, Mu, Ctx, V)
    ;   eval_expr(B, Mu, Ctx, V)
    ).
eval_expr(fn(coalesce, Args), Mu, Ctx, V) :-
    !,
    member(A, Args),
    eval_expr(A, Mu, Ctx, V),
    !.
eval_expr(agg(Name, Distinct, Arg, Sep), _, Ctx, V) :-
    !,
    Ctx = ctx(M, S, Members, C),
    Members \== none,
    aggregate_value(Name, Distinct, Arg, Sep, Members, ctx(M, S, none, C), V).
eval_expr(fn(Name, Args), Mu, Ctx, V) :-
    !,
    maplist(eval_arg(Mu, Ctx), Args, Vs),
    function(Name, Vs, V).
eval_expr(E, Mu, Ctx, V) :-
    arithmetic(E, Mu, Ctx, V).

eval_arg(Mu, Ctx, E, V) :-
    eval_expr(E, Mu, Ctx, V).

%   truth(+E, +Mu, +Ctx, -T): T is true, false or error.

truth(E, Mu, Ctx, T) :-
    (   eval_expr(E, Mu, Ctx, V),
        ebv(V, B)
    ->  T = B
    ;   T = error
    ).

or3(true, _, true) :- !.
or3(_, true, true) :- !.
or3(false, false, false).

and3(false, _, false) :- !.
and3(_, false, false) :- !.
and3(true, true, true).

negate(true, false).
negate(false, true).

boolean_term(B, literal(type(xsd:boolean, B))).

xsd_string(xsd:string).
xsd_boolean(xsd:boolean).

%   membership(+List, +V, +Mu, +Ctx, +Error0, -R): IN with errors.

membership([], _, _, _, Error, R) :-
    Error == false,
    R = false.
membership([E|Es], V, Mu, Ctx, Error0, R) :-
    (   eval_expr(E, Mu, Ctx, VE),
        compare_values(=, V, VE, Eq)
    ->  (   Eq == true
        ->  R = true
        ;   membership(Es, V, Mu, Ctx, Error0, R)
        )
    ;   membership(Es, V, Mu, Ctx, true, R)
    ).

exists(P, Mu, ctx(M, Subst0, _, C), R) :-
    merge_override(Mu, Subst0, Subst),
    (   eval(P, ctx(M, Subst, none, C), [], _)
    ->  R = true
    ;   R = false
    ).

merge_override(Mu, Subst0, Subst) :-
    findall(N-V, ( member(N-V, Subst0), \+ memberchk(N-_, Mu) ), Rest),
    append(Mu, Rest, Subst1),
    sort(1, @<, Subst1, Subst).

%   Effective boolean value (SPARQL 1.1 §17.2.2).

ebv(literal(type(T, Lex)), B) :-
    xsd_boolean(T),
    boolean_lexical(Lex, B0),
    !,
    B = B0.
ebv(T, B) :-
    value_class(T, C),
    ebv_class(C, B).

ebv_class(boolean(B), B).
ebv_class(string(Lex, _), B) :-
    (   Lex == ''
    ->  B = false
    ;   B = true
    ).
ebv_class(number(_, N), B) :-
    (   ( N =:= 0 ; N =\= N )
    ->  B = false
    ;   B = true
    ).
ebv_class(invalid(T, _), false) :-
    (   oro_numeric_datatype(T, _)
    ->  true
    ;   rdf_equal(T, xsd:boolean)
    ).

%   value_class(+Term, -Class): what an RDF term is for operators:
%   number(Kind, N), string(Lex, simple|xsd), lang(Lex, Tag),
%   boolean(B), datetime(Stamp), typed(Type, Lex), invalid(Type, Lex)
%   (ill-typed), iri(I) or bnode(B).

value_class(literal(V), C) :-
    !,
    literal_class(V, C).
value_class(X, C) :-
    atom(X),
    (   rdf_is_bnode(X)
    ->  C = bnode(X)
    ;   C = iri(X)
    ).

literal_class(type(T, Lex0), C) :-
    !,
    lexical_atom(Lex0, Lex),
    (   oro_numeric_datatype(T, Kind)
    ->  (   lexical_number(Kind, Lex, N)
        ->  C = number(Kind, N)
        ;   C = invalid(T, Lex)
        )
    ;   xsd_string(T)
    ->  C = string(Lex, xsd)
    ;   xsd_boolean(T)
    ->  (   boolean_lexical(Lex, B)
        ->  C = boolean(B)
        ;   C = invalid(T, Lex)
        )
    ;   date_type(T)
    ->  (   catch(parse_time(Lex, iso_8601, Stamp), _, fail)
        ->  C = datetime(Stamp)
        ;   C = invalid(T, Lex)
        )
    ;   C = typed(T, Lex)
    ).
literal_class(lang(Tag, Lex0), lang(Lex, Tag)) :-
    !,
    lexical_atom(Lex0, Lex).
literal_class(Lex0, string(Lex, simple)) :-
    lexical_atom(Lex0, Lex).

lexical_atom(X, A) :-
    (   atom(X)
    ->  A = X
    ;   format(atom(A), '~w', [X])
    ).

boolean_lexical(true, true).
boolean_lexical(false, false).
boolean_lexical('1', true).
boolean_lexical('0', false).

%   lexical_number(+Kind, +Lex, -N): XSD lexical forms.

lexical_number(integer, Lex, N) :-
    atom_codes(Lex, Codes0),
    phrase(xsd_integer, Codes0),
    strip_plus(Codes0, Codes),
    number_codes(N, Codes).
lexical_number(decimal, Lex, N) :-
    atom_codes(Lex, Codes0),
    phrase(xsd_decimal, Codes0),
    strip_plus(Codes0, Codes1),
    decimal_codes(Codes1, Codes),
    number_codes(N, Codes).
lexical_number(float, Lex, N) :-
    lexical_double(Lex, N).
lexical_number(double, Lex, N) :-
    lexical_double(Lex, N).

lexical_double('INF', N) :- !, N is inf.
lexical_double('+INF', N) :- !, N is inf.
lexical_double('-INF', N) :- !, N is -inf.
lexical_double('NaN', N) :- !, N is nan.
lexical_double(Lex, N) :-
    atom_codes(Lex, Codes0),
    phrase(xsd_double, Codes0),
    strip_plus(Codes0, Codes1),
    decimal_codes(Codes1, Codes),
    number_codes(N0, Codes),
    N is float(N0).

strip_plus([0'+|Cs], Cs) :- !.
strip_plus(Cs, Cs).

%   The lexical spaces of xsd:integer, xsd:decimal and xsd:double.

xsd_integer --> xsd_sign, digits(D), { D \== [] }.

xsd_decimal -->
    xsd_sign,
    digits(I),
    (   "."
    ->  digits(F),
        { I \== [] ; F \== [] }
    ;   { I \== [] }
    ).

xsd_double -->
    xsd_decimal,
    (   [E], { E == 0'e ; E == 0'E }
    ->  xsd_sign,
        digits(D),
        { D \== [] }
    ;   []
    ).

xsd_sign --> "+", !.
xsd_sign --> "-", !.
xsd_sign --> [].

%   decimal_codes(+Codes0, -Codes): make `.5`, `5.` and `5.e3` readable
%   by number_codes/2.

decimal_codes(Codes0, Codes) :-
    (   Codes0 = [0'-|Rest]
    ->  decimal_codes(Rest, Codes1),
        Codes = [0'-|Codes1]
    ;   Codes0 = [0'.|_]
    ->  decimal_codes([0'0|Codes0], Codes)
    ;   append(Int, [0'.|Frac], Codes0)
    ->  (   ( Frac == [] ; Frac = [E|_], memberchk(E, `eE`) )
        ->  append(Int, [0'., 0'0|Frac], Codes)
        ;   Codes = Codes0
        )
    ;   Codes = Codes0
    ),
    Codes \== [],
    Codes \== `-`.

%   Comparisons (SPARQL 1.1 §17.3, the operator mapping).

compare_values(=, A, B, R) :-
    !,
    equal_terms(A, B, R).
compare_values('!=', A, B, R) :-
    !,
    equal_terms(A, B, R0),
    negate(R0, R).
compare_values(Op, A, B, R) :-
    value_class(A, CA),
    value_class(B, CB),
    order_class(CA, CB, Order),
    (   order_satisfies(Op, Order)
    ->  R = true
    ;   R = false
    ).

order_satisfies(<, <).
order_satisfies(>, >).
order_satisfies('<=', <).
order_satisfies('<=', =).
order_satisfies('>=', >).
order_satisfies('>=', =).

equal_terms(A, B, R) :-
    (   A == B
    ->  R = true
    ;   atom(A)
    ->  R = false
    ;   atom(B)
    ->  R = false
    ;   value_class(A, CA),
        value_class(B, CB),
        equal_class(CA, CB, R)
    ).

equal_class(number(_, X), number(_, Y), R) :- !, truth_of(X =:= Y, R).
equal_class(string(X, _), string(Y, _), R) :- !, truth_of(X == Y, R).
equal_class(boolean(X), boolean(Y), R) :- !, truth_of(X == Y, R).
equal_class(datetime(X), datetime(Y), R) :- !, truth_of(X =:= Y, R).
equal_class(lang(X, TX), lang(Y, TY), R) :-
    !,
    downcase_atom(TX, LX),
    downcase_atom(TY, LY),
    truth_of(( X == Y, LX == LY ), R).
equal_class(iri(X), iri(Y), R) :- !, truth_of(X == Y, R).
equal_class(iri(_), _, false) :- !.
equal_class(_, iri(_), false) :- !.
equal_class(bnode(X), bnode(Y), R) :- !, truth_of(X == Y, R).
equal_class(bnode(_), _, false) :- !.
equal_class(_, bnode(_), false) :- !.
equal_class(typed(T, X), typed(T, Y), true) :-
    X == Y,
    !.
equal_class(invalid(T, X), invalid(T, Y), true) :-
    X == Y.

truth_of(Goal, R) :-
    (   call(Goal)
    ->  R = true
    ;   R = false
    ).

order_class(number(_, X), number(_, Y), O) :- !, number_order(X, Y, O).
order_class(string(X, _), string(Y, _), O) :- !, compare(O, X, Y).
order_class(boolean(X), boolean(Y), O) :- !, compare(O, X, Y).
order_class(datetime(X), datetime(Y), O) :- !, number_order(X, Y, O).

number_order(X, Y, O) :-
    (   X < Y
    ->  O = (<)
    ;   X > Y
    ->  O = (>)
    ;   X =:= Y
    ->  O = (=)
    ).

%   Arithmetic with numeric type promotion.

arithmetic(add(A, B), Mu, Ctx, V) :- binary(+, A, B, Mu, Ctx, V).
arithmetic(sub(A, B), Mu, Ctx, V) :- binary(-, A, B, Mu, Ctx, V).
arithmetic(mul(A, B), Mu, Ctx, V) :- binary(*, A, B, Mu, Ctx, V).
arithmetic(divide(A, B), Mu, Ctx, V) :- binary(/, A, B, Mu, Ctx, V).
arithmetic(neg(A), Mu, Ctx, V) :-
    eval_expr(A, Mu, Ctx, VA),
    numeric(VA, K, N),
    R is -N,
    number_term(K, R, V).
arithmetic(pos(A), Mu, Ctx, V) :-
    eval_expr(A, Mu, Ctx, VA),
    numeric(VA, K, N),
    number_term(K, N, V).

binary(Op, A, B, Mu, Ctx, V) :-
    eval_expr(A, Mu, Ctx, VA),
    eval_expr(B, Mu, Ctx, VB),
    numeric(VA, KA, NA),
    numeric(VB, KB, NB),
    promote(KA, KB, K0),
    (   Op == (/), K0 == integer
    ->  K = decimal
    ;   K = K0
    ),
    catch(compute(Op, K, NA, NB, R), _, fail),
    number_term(K, R, V).

compute(+, _, A, B, R) :- R is A + B.
compute(-, _, A, B, R) :- R is A - B.
compute(*, _, A, B, R) :- R is A * B.
compute(/, K, A, B, R) :-
    (   memberchk(K, [float, double])
    ->  R is float(A) / float(B)
    ;   B =\= 0,
        R0 is A / B,
        (   integer(R0)
        ->  R = R0
        ;   R is float(R0)
        )
    ).

promote(A, B, K) :-
    kind_rank(A, RA),
    kind_rank(B, RB),
    (   RA >= RB
    ->  K = A
    ;   K = B
    ).

numeric(T, Kind, N) :-
    value_class(T, number(Kind, N)).

%   number_term(+Kind, +N, -Literal)

number_term(integer, N, literal(type(T, Lex))) :-
    !,
    integer(N),
    rdf_equal(xsd:integer, T),
    atom_number(Lex, N).
number_term(decimal, N, literal(type(T, Lex))) :-
    !,
    rdf_equal(xsd:decimal, T),
    decimal_lexical(N, Lex).
number_term(Kind, N, Literal) :-
    F is float(N),
    double_lexical(F, Lex),
    kind_type(Kind, T),
    type_literal(T, Lex, Literal).

decimal_lexical(N, Lex) :-
    (   integer(N)
    ->  format(atom(Lex), '~d.0', [N])
    ;   N =:= float_integer_part(N),
        abs(N) < 1.0e15
    ->  I is integer(N),
        format(atom(Lex), '~d.0', [I])
    ;   format(atom(Lex0), '~15f', [N]),
        atom_codes(Lex0, Codes0),
        reverse(Codes0, R0),
        strip_zeros(R0, R),
        reverse(R, Codes),
        atom_codes(Lex, Codes)
    ).

strip_zeros([0'0, C|T], R) :-
    C \== 0'.,
    !,
    strip_zeros([C|T], R).
strip_zeros(R, R).

double_lexical(F, Lex) :-
    (   F =\= F
    ->  Lex = 'NaN'
    ;   F =:= inf
    ->  Lex = 'INF'
    ;   F =:= -inf
    ->  Lex = '-INF'
    ;   format(atom(Lex), '~w', [F])
    ).

		 /*******************************
		 *           FUNCTIONS          *
		 *******************************/

%   function(+Name, +Values, -Value) is semidet.

function(str, [X], V) :-
    (   X = literal(_)
    ->  literal_lexical(X, Lex)
    ;   atom(X),
        \+ rdf_is_bnode(X),
        Lex = X
    ),
    V = literal(Lex).
function(lang, [literal(L)], literal(Tag)) :-
    (   L = lang(Tag0, _)
    ->  Tag = Tag0
    ;   Tag = ''
    ).
function(datatype, [literal(L)], T) :-
    (   L = type(T0, _)
    ->  T = T0
    ;   L = lang(_, _)
    ->  rdf_equal(rdf:langString, T)
    ;   rdf_equal(xsd:string, T)
    ).
function(iri, [X], IRI) :-
    to_iri(X, IRI).
function(uri, [X], IRI) :-
    to_iri(X, IRI).
function(isiri, [X], V) :-
    truth_of(( atom(X), \+ rdf_is_bnode(X) ), R),
    boolean_term(R, V).
function(isuri, [X], V) :-
    function(isiri, [X], V).
function(isblank, [X], V) :-
    truth_of(( atom(X), rdf_is_bnode(X) ), R),
    boolean_term(R, V).
function(isliteral, [X], V) :-
    truth_of(X = literal(_), R),
    boolean_term(R, V).
function(isnumeric, [X], V) :-
    truth_of(numeric(X, _, _), R),
    boolean_term(R, V).
function(sameterm, [X, Y], V) :-
    truth_of(X == Y, R),
    boolean_term(R, V).
function(langmatches, [T, Range], V) :-
    simple_string(T, Tag),
    simple_string(Range, R0),
    downcase_atom(Tag, LTag),
    downcase_atom(R0, LRange),
    truth_of(tag_matches(LTag, LRange), R),
    boolean_term(R, V).
function(strlen, [X], V) :-
    string_arg(X, Lex, _),
    atom_length(Lex, N),
    number_term(integer, N, V).
function(ucase, [X], V) :-
    string_arg(X, Lex, Tag),
    upcase_atom(Lex, Up),
    string_term(Tag, Up, V).
function(lcase, [X], V) :-
    string_arg(X, Lex, Tag),
    downcase_atom(Lex, Low),
    string_term(Tag, Low, V).
function(contains, [X, Y], V) :-
    compatible_args(X, Y, A, B, _),
    truth_of(sub_atom(A, _, _, _, B), R),
    boolean_term(R, V).
function(strstarts, [X, Y], V) :-
    compatible_args(X, Y, A, B, _),
    truth_of(sub_atom(A, 0, _, _, B), R),
    boolean_term(R, V).
function(strends, [X, Y], V) :-
    compatible_args(X, Y, A, B, _),
    truth_of(sub_atom(A, _, _, 0, B), R),
    boolean_term(R, V).
function(strbefore, [X, Y], V) :-
    compatible_args(X, Y, A, B, Tag),
    (   sub_atom(A, Before, _, _, B)
    ->  sub_atom(A, 0, Before, _, Sub),
        string_term(Tag, Sub, V)
    ;   V = literal('')
    ).
function(strafter, [X, Y], V) :-
    compatible_args(X, Y, A, B, Tag),
    (   sub_atom(A, _, _, After, B)
    ->  sub_atom(A, _, After, 0, Sub),
        string_term(Tag, Sub, V)
    ;   V = literal('')
    ).
function(substr, [X, Start|Len], V) :-
    string_arg(X, Lex, Tag),
    numeric(Start, _, S0),
    S is round(S0),
    atom_length(Lex, N),
    (   Len = [L]
    ->  numeric(L, _, L0),
        E is S + round(L0)
    ;   E is N + 1
    ),
    From is max(1, S),
    To is min(N + 1, E),
    (   To > From
    ->  B is From - 1,
        Count is To - From,
        sub_atom(Lex, B, Count, _, Sub)
    ;   Sub = ''
    ),
    string_term(Tag, Sub, V).
function(concat, Args, V) :-
    maplist(string_arg_tag, Args, Lexes, Tags),
    atomic_list_concat(Lexes, Lex),
    (   Tags = [T|Ts],
        forall(member(T1, Ts), T1 == T),
        T \== simple
    ->  string_term(T, Lex, V)
    ;   V = literal(Lex)
    ).
function(encode_for_uri, [X], literal(Enc)) :-
    string_arg(X, Lex, _),
    encode_for_uri(Lex, Enc).
function(strlang, [X, L], literal(lang(Tag, Lex))) :-
    string_arg(X, Lex, Kind),
    Kind \= lang(_),
    simple_string(L, Tag),
    Tag \== ''.
function(strdt, [X, T], literal(type(T, Lex))) :-
    string_arg(X, Lex, Kind),
    Kind \= lang(_),
    atom(T),
    \+ rdf_is_bnode(T).
function(abs, [X], V) :-
    numeric(X, K, N),
    R is abs(N),
    number_term(K, R, V).
function(ceil, [X], V) :-
    numeric(X, K, N),
    rounded(ceiling, K, N, R),
    number_term(K, R, V).
function(floor, [X], V) :-
    numeric(X, K, N),
    rounded(floor, K, N, R),
    number_term(K, R, V).
function(round, [X], V) :-
    numeric(X, K, N),
    rounded(round, K, N, R),
    number_term(K, R, V).
function(regex, [X, P|Flags], V) :-
    string_arg(X, Text, _),
    simple_string(P, Pattern),
    flags_arg(Flags, FlagText),
    regex_match(Text, Pattern, FlagText, R),
    boolean_term(R, V).
function(replace, [X, P, W|Flags], V) :-
    string_arg(X, Text, Tag),
    simple_string(P, Pattern),
    simple_string(W, With),
    flags_arg(Flags, FlagText),
    regex_replace(Text, Pattern, With, FlagText, Result),
    string_term(Tag, Result, V).
function(cast(Kind), [X], V) :-
    cast(Kind, X, V).

tag_matches(Tag, '*') :-
    !,
    Tag \== ''.
tag_matches(Tag, Range) :-
    (   Tag == Range
    ->  true
    ;   atom_concat(Range, '-', Prefix),
        sub_atom(Tag, 0, _, _, Prefix)
    ).

rounded(_, integer, N, N) :- !.
rounded(round, _, N, R) :-
    !,
    R0 is floor(N + 0.5),
    R is float(R0).
rounded(F, _, N, R) :-
    G =.. [F, N],
    R0 is G,
    R is float(R0).

literal_lexical(literal(L), Lex) :-
    (   L = type(_, Lex0)
    ->  true
    ;   L = lang(_, Lex0)
    ->  true
    ;   Lex0 = L
    ),
    lexical_atom(Lex0, Lex).

to_iri(X, IRI) :-
    (   atom(X)
    ->  \+ rdf_is_bnode(X),
        IRI = X
    ;   string_arg(X, Lex, Tag),
        Tag \= lang(_),
        (   uri_is_global(Lex)
        ->  IRI = Lex
        ;   oro_default_namespace(NS),
            atom_concat(NS, Lex, IRI)
        )
    ).

%   String arguments (SPARQL 1.1 §17.4.3): simple literals, xsd:string
%   and language-tagged literals; Tag is simple, xsd or lang(L).

string_arg(literal(L), Lex, Tag) :-
    (   L = type(T, Lex0)
    ->  xsd_string(T),
        Tag = xsd
    ;   L = lang(Lang, Lex0)
    ->  Tag = lang(Lang)
    ;   Lex0 = L,
        Tag = simple
    ),
    lexical_atom(Lex0, Lex).

string_arg_tag(X, Lex, Tag) :-
    string_arg(X, Lex, Tag).

simple_string(X, Lex) :-
    string_arg(X, Lex, Tag),
    Tag \= lang(_).

string_term(simple, Lex, literal(Lex)).
string_term(xsd, Lex, literal(type(T, Lex))) :-
    rdf_equal(xsd:string, T).
string_term(lang(L), Lex, literal(lang(L, Lex))).

compatible_args(X, Y, A, B, Tag) :-
    string_arg(X, A, Tag),
    string_arg(Y, B, TagY),
    (   TagY \= lang(_)
    ->  true
    ;   TagY = lang(LY),
        Tag = lang(LX),
        downcase_atom(LX, L),
        downcase_atom(LY, L)
    ).

flags_arg([], '').
flags_arg([F], Flags) :-
    simple_string(F, Flags).

encode_for_uri(Lex, Enc) :-
    atom_codes(Lex, Codes),
    phrase(percent_encoded(Codes), EncCodes),
    atom_codes(Enc, EncCodes).

percent_encoded([]) --> [].
percent_encoded([C|Cs]) -->
    (   { C < 128, ( code_type(C, alnum) ; memberchk(C, `-_.~`) ) }
    ->  [C]
    ;   { utf8_bytes(C, Bytes) },
        percent_bytes(Bytes)
    ),
    percent_encoded(Cs).

utf8_bytes(C, [C]) :- C < 0x80, !.
utf8_bytes(C, [B1, B2]) :-
    C < 0x800,
    !,
    B1 is 0xC0 \/ (C >> 6),
    B2 is 0x80 \/ (C /\ 0x3F).
utf8_bytes(C, [B1, B2, B3]) :-
    C < 0x10000,
    !,
    B1 is 0xE0 \/ (C >> 12),
    B2 is 0x80 \/ ((C >> 6) /\ 0x3F),
    B3 is 0x80 \/ (C /\ 0x3F).
utf8_bytes(C, [B1, B2, B3, B4]) :-
    B1 is 0xF0 \/ (C >> 18),
    B2 is 0x80 \/ ((C >> 12) /\ 0x3F),
    B3 is 0x80 \/ ((C >> 6) /\ 0x3F),
    B4 is 0x80 \/ (C /\ 0x3F).

percent_bytes([]) --> [].
percent_bytes([B|Bs]) -->
    { format(codes(Hex), '%~|~`0t~16R~2+', [B]) },
    Hex,
    percent_bytes(Bs).

%   XSD casts (SPARQL 1.1 §17.5).

cast(string, X, V) :-
    function(str, [X], literal(Lex)),
    string_term(xsd, Lex, V).
cast(boolean, X, V) :-
    (   value_class(X, boolean(B))
    ->  true
    ;   numeric(X, _, N)
    ->  (   ( N =:= 0 ; N =\= N )
        ->  B = false
        ;   B = true
        )
    ;   simple_string(X, Lex),
        boolean_lexical(Lex, B)
    ),
    boolean_term(B, V).
cast(Kind, X, V) :-
    memberchk(Kind, [integer, decimal, float, double]),
    (   value_class(X, boolean(B))
    ->  (   B == true -> N0 = 1 ; N0 = 0 )
    ;   numeric(X, _, N0)
    ->  true
    ;   simple_string(X, Lex),
        normalize_space(atom(Lex1), Lex),
        lexical_number(Kind, Lex1, N0)
    ),
    cast_number(Kind, N0, N),
    number_term(Kind, N, V).

cast_number(integer, N0, N) :-
    !,
    N0 =:= N0,
    N0 =\= inf, N0 =\= -inf,
    N is truncate(N0).
cast_number(decimal, N0, N) :-
    !,
    N0 =:= N0,
    N0 =\= inf, N0 =\= -inf,
    N = N0.
cast_number(_, N0, N) :-
    N is float(N0).

%   Regular expressions (XPath syntax, run by PCRE).

regex_options(Flags, Options, Quote) :-
    atom_codes(Flags, Codes),
    foldl(regex_flag, Codes, opts([], false), opts(Options, Quote)).

regex_flag(0'i, opts(O, Q), opts([caseless(true)|O], Q)).
regex_flag(0's, opts(O, Q), opts([dotall(true)|O], Q)).
regex_flag(0'm, opts(O, Q), opts([multiline(true)|O], Q)).
regex_flag(0'x, opts(O, Q), opts([extended(true)|O], Q)).
regex_flag(0'q, opts(O, _), opts(O, true)).

regex_pattern(Pattern0, Quote, Pattern) :-
    (   Quote == true
    ->  atom_codes(Pattern0, Codes0),
        foldl(quote_code, Codes0, Codes, []),
        string_codes(Pattern, Codes)
    ;   atom_string(Pattern0, Pattern)
    ).

quote_code(C, [0'\\, C|T], T) :-
    memberchk(C, `\\^$.|?*+()[]{}`),
    !.
quote_code(C, [C|T], T).

:- if(current_predicate(re_match/3)).

regex_match(Text, Pattern0, Flags, R) :-
    regex_options(Flags, Options, Quote),
    regex_pattern(Pattern0, Quote, Pattern),
    atom_string(Text, String),
    catch(( re_match(Pattern, String, Options)
          ->  R = true
          ;   R = false
          ),
          _, fail).

regex_replace(Text, Pattern0, With, Flags, Result) :-
    regex_options(Flags, Options, Quote),
    regex_pattern(Pattern0, Quote, Pattern),
    atom_string(Text, String),
    atom_string(With, WithString),
    catch(re_replace(Pattern/g, WithString, String, Result0, Options),
          _, fail),
    atom_string(Result, Result0).

:- else.

regex_match(_, _, _, _) :-
    fail.
regex_replace(_, _, _, _, _) :-
    fail.

:- endif.

		 /*******************************
		 *          AGGREGATES          *
		 *******************************/

%   aggregate_value(+Name, +Distinct, +Arg, +Sep, +Members, +Ctx, -Value)

aggregate_value(count, Distinct, star, _, Members, _, V) :-
    !,
    (   Distinct == distinct
    ->  sort(Members, Ms)
    ;   Ms = Members
    ),
    length(Ms, N),
    number_term(integer, N, V).
aggregate_value(Name, Distinct, Arg, Sep, Members, Ctx, V) :-
    findall(R, ( member(Mu, Members),
                 (   eval_expr(Arg, Mu, Ctx, X)
                 ->  R = ok(X)
                 ;   R = error
                 )
               ), Results),
    (   Distinct == distinct
    ->  list_to_set(Results, Results1)
    ;   Results1 = Results
    ),
    aggregate_results(Name, Results1, Sep, V).

aggregate_results(count, Results, _, V) :-
    aggregate_all(count, member(ok(_), Results), N),
    number_term(integer, N, V).
aggregate_results(sum, Results, _, V) :-
    \+ memberchk(error, Results),
    foldl(sum_value, Results, integer-0, K-N),
    number_term(K, N, V).
aggregate_results(avg, Results, _, V) :-
    \+ memberchk(error, Results),
    (   Results == []
    ->  number_term(integer, 0, V)
    ;   foldl(sum_value, Results, integer-0, K0-Sum),
        length(Results, Count),
        promote(K0, decimal, K),
        Avg is Sum / Count,
        number_term(K, Avg, V)
    ).
aggregate_results(min, Results, _, V) :-
    findall(X, member(ok(X), Results), [X0|Xs]),
    foldl(min_value, Xs, X0, V).
aggregate_results(max, Results, _, V) :-
    findall(X, member(ok(X), Results), [X0|Xs]),
    foldl(max_value, Xs, X0, V).
aggregate_results(sample, Results, _, V) :-
    memberchk(ok(V), Results).
aggregate_results(group_concat, Results, Sep, literal(Lex)) :-
    findall(S, ( member(ok(X), Results),
                 function(str, [X], literal(S))
               ), Strings),
    atomic_list_concat(Strings, Sep, Lex).

sum_value(ok(X), K0-N0, K-N) :-
    numeric(X, KX, NX),
    promote(K0, KX, K),
    N is N0 + NX.

min_value(X, V0, V) :-
    term_order(X, V0, O),
    (   O == (<)
    ->  V = X
    ;   V = V0
    ).

max_value(X, V0, V) :-
    term_order(X, V0, O),
    (   O == (>)
    ->  V = X
    ;   V = V0
    ).

		 /*******************************
		 *         JSON RESULTS         *
		 *******************************/

%   result_json(+Result, -JSON): SPARQL 1.1 Query Results JSON Format.

result_json(ask(Bool), JSON) :-
    format(string(JSON), '{"head":{},"boolean":~w}', [Bool]).
result_json(select(Vars, Rows), JSON) :-
    with_output_to(string(JSON),
                   ( write('{"head":{"vars":['),
                     write_separated(Vars, json_string),
                     write(']},"results":{"bindings":['),
                     write_separated(Rows, json_row),
                     write(']}}')
                   )).

write_separated([], _).
write_separated([H|T], Writer) :-
    call(Writer, H),
    forall(member(X, T),
           ( write(','),
             call(Writer, X)
           )).

json_row(Row) :-
    write('{'),
    write_separated(Row, json_binding),
    write('}').

json_binding(Name-Value) :-
    json_string(Name),
    write(':'),
    json_term(Value).

json_term(literal(L)) :-
    !,
    write('{"type":"literal","value":'),
    (   L = lang(Lang, Lex)
    ->  json_string(Lex),
        write(',"xml:lang":'),
        json_string(Lang)
    ;   L = type(T, Lex)
    ->  json_string(Lex),
        write(',"datatype":'),
        json_string(T)
    ;   json_string(L)
    ),
    write('}').
json_term(X) :-
    rdf_is_bnode(X),
    !,
    (   atom_concat('_:', Label, X)
    ->  true
    ;   Label = X
    ),
    write('{"type":"bnode","value":'),
    json_string(Label),
    write('}').
json_term(IRI) :-
    write('{"type":"uri","value":'),
    json_string(IRI),
    write('}').

json_string(Text) :-
    lexical_atom(Text, Atom),
    atom_codes(Atom, Codes),
    put_char('"'),
    maplist(json_char, Codes),
    put_char('"').

json_char(0'") :- !, write('\\"').
json_char(0'\\) :- !, write('\\\\').
json_char(0'\n) :- !, write('\\n').
json_char(0'\r) :- !, write('\\r').
json_char(0'\t) :- !, write('\\t').
json_char(C) :- C < 0x20, !, format('\\u~|~`0t~16r~4+', [C]).
json_char(C) :- put_char(C).
