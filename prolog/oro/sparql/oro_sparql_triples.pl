:- module(oro_sparql_triples,
          [ triples_same_subject//2,    % +St, -Triples
            new_bgp/1,                  % +St
            forget_bnode_labels/1,      % +St
            iri//2,                     % +St, -IRI
            resolve_iri/4,              % +St, +Text, +Pos, -IRI
            rdf_literal//2,             % +St, -Literal
            boolean_literal//1,         % -Literal
            data_block//2               % +St, -Values
          ]).
:- use_module(library(semweb/rdf_db)).
:- use_module(library(lists)).
:- use_module(library(apply)).
:- use_module(library(pairs)).
:- use_module(library(uri)).
:- use_module(library(oro/oro_names)).
:- use_module(library(oro/sparql/oro_sparql_syntax)).
:- use_module(library(oro/sparql/oro_sparql_functions), [kind_type/2]).

/** <module> The SPARQL grammar: triples, property paths, terms, values

The productions of the W3C SPARQL 1.1 grammar below graph patterns:
triples with their property and object lists, blank node property lists
and collections, property paths (normalized to links, inverses and
negated property sets where SPARQL 1.1 §18.4 allows), RDF terms (IRIs,
prefixed names, literals, blank nodes) and the data blocks of VALUES.
oro_sparql_grammar builds on them.
*/

		 /*******************************
		 *      PARSING: TRIPLES        *
		 *******************************/

%!  triples_same_subject(+St, -Triples)// is semidet.
%
%   Triples (rdf(S, P, O) and path(S, Path, O) terms) are those of a
%   TriplesSameSubjectPath: a subject (or a blank node property list
%   or collection) and its property list.

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
    ;   tokp(bnode(L), P)
    ->  { bnode_label_use(St, L, P),
          atom_concat('_:b_', L, N),
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

%   Blank node labels: a label names one blank node of one basic graph
%   pattern, and may not be used in another (SPARQL 1.1 §19.6).  The
%   state's counter(N, Labels, Block) holds the labels seen, each
%   Label-Block, and the current basic graph pattern: a group, and any
%   element of a group but a FILTER, begins a new one.

%!  new_bgp(+St) is det.
%
%   A new basic graph pattern begins.

new_bgp(st(_, _, Counter, _)) :-
    arg(1, Counter, N0),
    N is N0 + 1,
    nb_setarg(1, Counter, N),
    nb_setarg(3, Counter, N).

bnode_label_use(st(_, _, Counter, _), Label, P) :-
    arg(2, Counter, Labels),
    arg(3, Counter, Block),
    (   memberchk(Label-Block0, Labels)
    ->  (   Block0 == Block
        ->  true
        ;   semantic_error("Blank node label _:~w used in two basic graph \c
                            patterns", [Label], P)
        )
    ;   nb_setarg(2, Counter, [Label-Block|Labels])
    ).

%!  forget_bnode_labels(+St) is det.
%
%   The labels of a CONSTRUCT template are its own: the WHERE clause
%   may use them again.

forget_bnode_labels(st(_, _, Counter, _)) :-
    nb_setarg(2, Counter, []).

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

%!  iri(+St, -IRI)// is semidet.
%
%   IRI is an IRI (written in full, relative, or as a prefixed name).

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

%!  resolve_iri(+St, +Text, +Pos, -IRI) is det.
%
%   Absolute IRIs are kept; relative ones are resolved against BASE,
%   or, without BASE, taken as names in the default namespace (as ORO
%   names are).

resolve_iri(St, Text, _, IRI) :-
    (   uri_is_global(Text)
    ->  IRI = Text
    ;   St = st(_, Base, _, _),
        Base \== none
    ->  uri_resolve(Text, Base, IRI)
    ;   oro_default_namespace(NS),
        atom_concat(NS, Text, IRI)
    ).

%!  rdf_literal(+St, -Literal)// is semidet.
%
%   Literal is a string literal, with its language tag or datatype.

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
    ->  { Sign = '+' }
    ;   { Sign = '' }
    ),
    tok(num(Kind, Lex0)),
    { atom_concat(Sign, Lex0, Lex),
      kind_type(Kind, Type),
      T = literal(type(Type, Lex))
    }.

%!  boolean_literal(-Literal)// is semidet.
%
%   Literal is the xsd:boolean `true` or `false`.

boolean_literal(literal(type(T, B))) -->
    tok(word(B, _)),
    { memberchk(B, [true, false]),
      rdf_equal(xsd:boolean, T)
    }.

%!  data_block(+St, -Values)// is semidet.
%
%   Values is values(Vars, Rows), the data of a VALUES block.

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
