:- module(oro_sparql_grammar,
          [ parse_text/3,               % +What, +Text, -Term
            sparql_error/3,             % +Message, +Position, +Text
            conjunction/2,              % +Exprs, -Expr
            free_variables/2            % +Expr, -Names
          ]).
:- use_module(library(semweb/rdf_db)).
:- use_module(library(lists)).
:- use_module(library(apply)).
:- use_module(library(pairs)).
:- use_module(library(uri)).
:- use_module(library(oro/oro_names)).
:- use_module(library(oro/sparql/oro_sparql_lexer), [tokenize/2]).
:- use_module(library(oro/sparql/oro_sparql_syntax)).
:- use_module(library(oro/sparql/oro_sparql_triples)).
:- use_module(library(oro/sparql/oro_sparql_expressions)).

/** <module> The SPARQL grammar: text to algebra

A DCG over the tokens of oro_sparql_lexer following the productions of
the W3C SPARQL 1.1 grammar, producing the SPARQL algebra term that
oro_sparql:oro_sparql_parse/2 documents.  Prefixes (those of
oro_prefix/2 and `:` for the default namespace) are predeclared.  A
query that does not parse raises a syntax error naming the line, the
column and what was expected at the furthest position reached.

This module holds the driver and the mutually recursive productions
of queries and graph patterns (a sub-select is a graph pattern, a
graph pattern is the WHERE of a query); its parts are
oro_sparql_syntax (token primitives and errors), oro_sparql_triples
(triples, property paths, RDF terms, VALUES data) and
oro_sparql_expressions (expressions, whose EXISTS calls back here
through the hook oro_sparql_expressions:exists_pattern//2).
*/

		 /*******************************
		 *       PARSING: DRIVER        *
		 *******************************/

%!  parse_text(+What, +Text, -Term) is det.
%
%   Term is the algebra of Text parsed as What: `query` (a whole query)
%   or `expression` (a FILTER expression).
%
%   @error syntax_error(oro_sparql(Message, Position)) if Text does not
%          parse.

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

initial_state(st(Prefixes, none, counter(0, [], 0), no_aggregates)) :-
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

%!  sparql_error(+Message, +Position, +Text) is det.
%
%   Throw the syntax error of Message at the 0-based character Position
%   of Text (a string or a code list): its message names the line and
%   column.

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

		 /*******************************
		 *      PARSING: QUERIES        *
		 *******************************/

query_unit(St0, Query) -->
    prologue(St0, St),
    (   kw(select)
    ->  select_query(St, Query0, Dataset)
    ;   kw(ask)
    ->  ask_query(St, Query0, Dataset)
    ;   kw(construct)
    ->  construct_query(St, Query0, Dataset)
    ;   kw(describe)
    ->  describe_query(St, Query0, Dataset)
    ;   unsupported_form
    ),
    values_clause(St, Values),
    { add_values(Query0, Values, Query1),
      (   Dataset == []
      ->  Query = Query1
      ;   findall(G, member(default(G), Dataset), Defaults),
          findall(G, member(named(G), Dataset), Named),
          Query = from(Defaults, Named, Query1)
      )
    },
    tok(eof).

unsupported_form -->
    tokp(word(W, Word), P),
    { memberchk(W, [insert, delete, load, clear, create, drop, with, add,
                    move, copy]),
      upcase_atom(Word, Up),
      semantic_error("~w is not supported (updates are refused: only \c
                      SELECT, ASK, CONSTRUCT and DESCRIBE queries)",
                     [Up], P)
    }.

%   CONSTRUCT: a template of triples, instantiated by each solution.
%   Blank nodes of the template are tbnode(Label), fresh for each
%   solution; those of the WHERE clause are hidden variables.

construct_query(St, construct(Template, Pattern, Mods), Dataset) -->
    (   peek_punct('{')
    ->  tok(punct('{')),
        template_triples(St, Triples),
        tok(punct('}')),
        { forget_bnode_labels(St) },
        dataset_clauses(St, Dataset),
        where_clause(St, Pattern)
    ;   dataset_clauses(St, Dataset),
        kw(where),
        tok(punct('{')),
        template_triples(St, Triples),
        tok(punct('}')),
        { Pattern = bgp(Triples) }
    ),
    solution_modifier(St, m(Group, Having, Order, Offset, Limit)),
    { maplist(template_triple, Triples, Template),
      Mods = mods(false, Group, Having, Order, Offset, Limit, none)
    }.

template_triples(St, Triples) -->
    (   triples_block(St, Triples0)
    ->  { Triples = Triples0 }
    ;   { Triples = [] }
    ).

template_triple(rdf(S0, P0, O0), rdf(S, P, O)) :-
    !,
    maplist(template_node, [S0, P0, O0], [S, P, O]).
template_triple(path(S0, link(P), O0), rdf(S, P, O)) :-
    !,
    maplist(template_node, [S0, O0], [S, O]).
template_triple(T, _) :-
    semantic_error("CONSTRUCT template: property paths are not allowed: ~q",
                   [T], 0).

template_node(var(N), T) :-
    !,
    (   hidden_variable(N)
    ->  T = tbnode(N)
    ;   T = var(N)
    ).
template_node(T, T).

%   DESCRIBE: the resources (IRIs and variables, or `*`) to describe.

describe_query(St, describe(Terms, Pattern, Mods), Dataset) -->
    (   tok(punct(*))
    ->  { Terms = star }
    ;   describe_term(St, T),
        describe_terms(St, Ts),
        { Terms = [T|Ts] }
    ),
    dataset_clauses(St, Dataset),
    (   ( peek_kw(where) ; peek_punct('{') )
    ->  where_clause(St, Pattern)
    ;   { Pattern = bgp([]) }
    ),
    solution_modifier(St, m(Group, Having, Order, Offset, Limit)),
    { Mods = mods(false, Group, Having, Order, Offset, Limit, none) }.

describe_terms(St, [T|Ts]) -->
    describe_term(St, T),
    !,
    describe_terms(St, Ts).
describe_terms(_, []) --> [].

describe_term(_, var(N)) -->
    tok(var(N)),
    !.
describe_term(St, IRI) -->
    iri(St, IRI).

add_values(select(Pr, D, P, mods(A, G, H, O, Off, L, _)), Values,
           select(Pr, D, P, mods(A, G, H, O, Off, L, Values))).
add_values(ask(P, mods(A, G, H, O, Off, L, _)), Values,
           ask(P, mods(A, G, H, O, Off, L, Values))).
add_values(construct(T, P, mods(A, G, H, O, Off, L, _)), Values,
           construct(T, P, mods(A, G, H, O, Off, L, Values))).
add_values(describe(T, P, mods(A, G, H, O, Off, L, _)), Values,
           describe(T, P, mods(A, G, H, O, Off, L, Values))).

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

select_query(St, Query, Dataset) -->
    select_clause(St, Distinct, Proj0),
    dataset_clauses(St, Dataset),
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

%   dataset_clauses(+St, -Dataset): FROM and FROM NAMED, a list of
%   default(IRI) and named(IRI).

dataset_clauses(St, [D|Ds]) -->
    kw(from),
    !,
    (   kw(named)
    ->  iri(St, IRI),
        { D = named(IRI) }
    ;   iri(St, IRI),
        { D = default(IRI) }
    ),
    dataset_clauses(St, Ds).
dataset_clauses(_, []) --> [].

where_clause(St, Pattern) -->
    (   kw(where)
    ->  []
    ;   []
    ),
    group_graph_pattern(St, Pattern).

ask_query(St, ask(Pattern, Mods), Dataset) -->
    dataset_clauses(St, Dataset),
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

%!  free_variables(+Expr, -Names) is det.
%
%   Names is the ordered set of the variables of Expr outside
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

		 /*******************************
		 *   PARSING: GRAPH PATTERNS    *
		 *******************************/

group_graph_pattern(St0, Pattern) -->
    { no_aggregates(St0, St),
      new_bgp(St)
    },
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
    here(P),
    select_query(St, Query0, Dataset),
    { Dataset == []
    ->  true
    ;   semantic_error("FROM is not allowed in a sub-select", [], P)
    },
    values_clause(St, Values),
    { add_values(Query0, Values, Query) }.

group_elements(St, Elems) -->
    triples_block_opt(St, Elems, Elems1),
    group_elements_rest(St, Elems1).

group_elements_rest(St, Elems) -->
    (   pattern_not_triples(St, E)
    ->  { Elems = [E|Elems1],
          (   E = filter(_)
          ->  true
          ;   new_bgp(St)
          )
        },
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
    ;   kw(graph)
    ->  graph_name_term(St, T),
        group_graph_pattern(St, P),
        { E = graph(T, P) }
    ;   tokp(word(W, Word), P),
        { W == service,
          upcase_atom(Word, Up),
          semantic_error("~w is not supported (no federated queries)",
                         [Up], P)
        }
    ).

graph_name_term(_, var(N)) -->
    tok(var(N)),
    !.
graph_name_term(St, IRI) -->
    iri(St, IRI).

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
    (   G == bgp([]),
        P = filter(_, _)
    ->  G1 = join(G, P)             % not simplified: an OPTIONAL whose
    ;   join_patterns(G, P, G1)     % group is a group with a FILTER
    ).                              % keeps that FILTER inside
group_element(values(Vs, Rows), g(G, Fs), g(G1, Fs)) :-
    join_patterns(G, values(Vs, Rows), G1).
group_element(graph(T, P), g(G, Fs), g(G1, Fs)) :-
    join_patterns(G, graph(T, P), G1).

join_patterns(bgp([]), P, P) :- !.
join_patterns(bgp(A), bgp(B), bgp(C)) :- !, append(A, B, C).
join_patterns(G, P, join(G, P)).

true_expression(const(literal(type(T, true)))) :-
    rdf_equal(xsd:boolean, T).

%!  conjunction(+Exprs, -Expr) is det.
%
%   Expr is the `&&` of the expressions Exprs (a non-empty list).

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
scope(graph(T, P)) --> scope_node(T), scope(P).
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

%   EXISTS and NOT EXISTS in an expression (oro_sparql_expressions)
%   parse their pattern here.

oro_sparql_expressions:exists_pattern(St, Pattern) -->
    group_graph_pattern(St, Pattern).
