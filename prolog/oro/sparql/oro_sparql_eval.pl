:- module(oro_sparql_eval,
          [ run_query/3,                % +Dataset, +Query, -Result
            eval/4                      % +Pattern, +Ctx, +Mu0, -Mu
          ]).
:- use_module(library(semweb/rdf_db)).
:- use_module(library(lists)).
:- use_module(library(apply)).
:- use_module(library(pairs)).
:- use_module(library(ordsets)).
:- use_module(library(assoc)).
:- use_module(library(oro/reason/oro_reason)).
:- use_module(library(oro/oro_store), [oro_asserted/4]).
:- use_module(library(solution_sequences), [distinct/2]).
:- use_module(library(oro/sparql/oro_sparql_algebra), [annotate_query/2, plan_goals/5, memo/4]).
:- use_module(library(oro/sparql/oro_sparql_functions), [eval_expr/4, expr_true/3]).
:- use_module(library(oro/sparql/oro_sparql_terms), [term_order/3, lookup/4]).

/** <module> The SPARQL evaluator

Evaluates the annotated algebra (oro_sparql_algebra) of a query over
oro_holds/4, the inference closure of a model: joins pass solutions
sideways, basic graph patterns run in the order of their plan,
property paths have the distinct-node semantics of SPARQL 1.1, and
solution modifiers (grouping, ordering, projection, DISTINCT, OFFSET,
LIMIT) apply in the order of the specification.
*/

		 /*******************************
		 *         QUERY RUNNER         *
		 *******************************/

%   The evaluation context: ctx(Dataset, Subst, Group, Cache), Dataset
%   ds(Default, Named) (see run_query/3), Subst the
%   bindings EXISTS substitutes (Name-Value, sorted), Group the member
%   solutions of the current group (or `none`), Cache a mutable
%   cache(Assoc) of cost estimates.

%!  run_query(+Dataset, +Query, -Result) is det.
%
%   Result is select(Vars, Rows), ask(Bool) or graph(Triples) (CONSTRUCT
%   and DESCRIBE; a sorted list of rdf(S, P, O)), the result of the
%   algebra Query (from oro_sparql_grammar) over Dataset,
%   ds(Default, Named).  Default is the default graph: a model (its
%   inference closure), asserted(Model) (the triples visible in Model,
%   without inference) or graphs(Graphs) (the RDF merge of the rdf_db
%   graphs Graphs).  Named lists the named graphs as IRI-Graphs.

run_query(Dataset, Query0, Result) :-
    annotate_query(Query0, Query),
    empty_assoc(Empty),
    Ctx = ctx(Dataset, [], none, cache(Empty)),
    query_result(Query, Ctx, Result).

query_result(select(Proj, D, P, Mods), Ctx, select(Vars, Rows)) :-
    projection_names(Proj, Vars),
    select_rows(select(Proj, D, P, Mods), Ctx, Rows).
query_result(construct(Template, P, Mods), Ctx, graph(Triples)) :-
    template_variables(Template, Vars),
    findall(var(V), member(V, Vars), Proj),
    select_rows(select(Proj, all, P, Mods), Ctx, Rows),
    findall(Triple, ( nth1(I, Rows, Row),
                      member(T, Template),
                      instantiate(T, I, Row, Triple)
                    ), Triples0),
    sort(Triples0, Triples).
query_result(describe(Terms0, P, Mods), Ctx, graph(Triples)) :-
    (   Terms0 == star
    ->  P = p(Certain, _),
        findall(var(V), member(V, Certain), Terms)
    ;   Terms = Terms0
    ),
    findall(var(V), member(var(V), Terms), Proj),
    select_rows(select(Proj, all, P, Mods), Ctx, Rows),
    findall(R, ( member(R, Terms), atom(R)
               ; member(Row, Rows), member(_-R, Row)
               ), Resources0),
    sort(Resources0, Resources),
    findall(Triple, ( member(R, Resources),
                      described(R, Ctx, Triple)
                    ), Triples0),
    sort(Triples0, Triples).
query_result(ask(P, mods(A, G, H, O, Off, Lim0, V)), Ctx, ask(Bool)) :-
    Lim is min(Lim0, 1),
    select_rows(select([], all, P, mods(A, G, H, O, Off, Lim, V)), Ctx, Rows),
    (   Rows == []
    ->  Bool = false
    ;   Bool = true
    ).

%   template_variables(+Template, -Vars): the variables of a
%   CONSTRUCT template.

template_variables(Template, Vars) :-
    findall(V, ( member(rdf(S, P, O), Template),
                 member(var(V), [S, P, O])
               ), Vars0),
    sort(Vars0, Vars).

%   instantiate(+TemplateTriple, +I, +Row, -Triple): the triple of the
%   I-th solution Row; fails if a variable is unbound or the triple is
%   not RDF (a literal subject, a predicate that is not an IRI).

instantiate(rdf(S0, P0, O0), I, Row, rdf(S, P, O)) :-
    template_term(S0, I, Row, S),
    template_term(P0, I, Row, P),
    template_term(O0, I, Row, O),
    atom(S),
    atom(P),
    \+ rdf_is_bnode(P).

template_term(var(N), _, Row, V) :-
    !,
    memberchk(N-V, Row).
template_term(tbnode(N), I, _, B) :-
    !,
    atom_concat('_:', Label, N),
    format(atom(B), '_:c~d~w', [I, Label]).
template_term(T, _, _, T).

%   described(+Resource, +Ctx, -Triple): the triples describing a
%   resource: those of which it is the subject, and recursively those
%   of the blank nodes they reach (its concise bounded description,
%   without reification).

described(R, Ctx, Triple) :-
    described(R, Ctx, [R], Triple).

described(R, Ctx, Seen, Triple) :-
    findall(rdf(R, P, O), triple(Ctx, R, P, O), Triples),
    member(rdf(R, P, O), Triples),
    (   Triple = rdf(R, P, O)
    ;   rdf_is_bnode(O),
        \+ memberchk(O, Seen),
        described(O, Ctx, [O|Seen], Triple)
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

		 /*******************************
		 *      PATTERN EVALUATION      *
		 *******************************/

%!  eval(+Pattern, +Ctx, +Mu0, -Mu) is nondet.
%
%   Mu is a solution of Join({Mu0}, Pattern), Pattern annotated.

eval(p(Certain, Op), Ctx, Mu0, Mu) :-
    restrict(Mu0, Certain, In),
    solve(Op, Ctx, In, Mu1),
    merge_solutions(Mu0, Mu1, Mu).

%   EXISTS in an expression (oro_sparql_functions) evaluates its
%   pattern here.

oro_sparql_functions:pattern_exists(P, Ctx) :-
    eval(P, Ctx, [], _).

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
solve(graph(T, P), Ctx, In, Mu) :-
    Ctx = ctx(ds(_, Named), Subst, Group, Cache),
    (   T = var(N)
    ->  (   memberchk(N-IRI, In)
        ->  true
        ;   memberchk(N-IRI, Subst)
        ->  true
        ;   true
        ),
        member(IRI-Graphs, Named),
        eval(P, ctx(ds(graphs(Graphs), Named), Subst, Group, Cache), In, Mu1),
        put_binding(N, IRI, Mu1, Mu)
    ;   memberchk(T-Graphs, Named),
        eval(P, ctx(ds(graphs(Graphs), Named), Subst, Group, Cache), In, Mu)
    ).
solve(subselect(Query, Cache), Ctx, In, Mu) :-
    subselect_rows(Query, Cache, Ctx, Rows),
    member(Row, Rows),
    sort(1, @<, Row, Mu),
    compatible(In, Mu).

%   subselect_rows(+Query, +Cache, +Ctx, -Rows): the rows of a
%   sub-select, computed once per active graph (GRAPH ?g { SELECT ... }
%   has one table per named graph) when no outer binding is substituted.

subselect_rows(Query, Cache, Ctx, Rows) :-
    Ctx = ctx(ds(Source, _), Subst, _, _),
    (   Subst == [],
        arg(1, Cache, rows(Tables)),
        memberchk(Source-Rows0, Tables)
    ->  Rows = Rows0
    ;   Query = select(Proj, D, P, Mods),
        group_context(Ctx, none, Ctx1),
        select_rows(select(Proj, D, P, Mods), Ctx1, Rows),
        (   Subst == []
        ->  (   arg(1, Cache, rows(Tables0))
            ->  true
            ;   Tables0 = []
            ),
            nb_setarg(1, Cache, rows([Source-Rows|Tables0]))
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

triple(ctx(ds(Source, _), _, _, _), S, P, O) :-
    resource_or_var(S),
    resource_or_var(P),
    source_triple(Source, S, P, O).

%   source_triple(+Source, ?S, ?P, ?O): S-P-O is a triple of the
%   default graph Source: a model (its inference closure),
%   asserted(Model) (the triples visible in Model, without inference)
%   or graphs(Graphs) (the RDF merge of the rdf_db graphs Graphs).
%   Each triple comes once.

source_triple(asserted(Model), S, P, O) :-
    !,
    stored_object(O, O1, Test),
    distinct(t(S, P, O1), oro_asserted(Model, S, P, O1)),
    call(Test).
source_triple(graphs(Graphs), S, P, O) :-
    !,
    stored_object(O, O1, Test),
    (   Graphs = [Graph]
    ->  rdf(S, P, O1, Graph)
    ;   distinct(t(S, P, O1), ( member(Graph, Graphs),
                                rdf(S, P, O1, Graph)
                              ))
    ),
    call(Test).
source_triple(Model, S, P, O) :-
    oro_holds(Model, S, P, O).

%   stored_object(+O, -Pattern, -Test): language tags are case
%   insensitive (RDF 1.1): a language-tagged constant "x"@EN matches the
%   stored "x"@en; rdf_db compares tags as they are written.  A simple
%   literal "x" (the same term as "x"^^xsd:string, which rdf_db stores
%   as "x") matches only itself: rdf_db's literal(x) would also match
%   "x"@en and "x"^^T.

stored_object(O, Pattern, Test) :-
    (   nonvar(O),
        O = literal(lang(Lang, Lex)),
        atom(Lang)
    ->  Pattern = literal(lang(Stored, Lex)),
        Test = same_language(Lang, Stored)
    ;   nonvar(O),
        O = literal(Lex),
        atom(Lex)
    ->  Pattern = literal(exact(Lex), Stored),
        Test = (Stored == Lex)
    ;   Pattern = O,
        Test = true
    ).

same_language(A, B) :-
    atom(B),
    downcase_atom(A, L),
    downcase_atom(B, L).

resource_or_var(X) :-
    (   var(X)
    ->  true
    ;   atom(X)
    ).

		 /*******************************
		 *        PROPERTY PATHS        *
		 *******************************/

%   path_holds(+Path, +Ctx, ?S, ?O): arbitrary-length paths have the
%   distinct-node semantics of SPARQL 1.1 (each end once).  With both
%   ends unbound, the zero-length matches of `*` and `?` are every node
%   (subject or object) of the active graph (SPARQL 1.1 §18.4,
%   ZeroLengthPath).

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
    ;   start_nodes(How, P, Ctx, Nodes),
        member(S, Nodes),
        reached(How, P, fwd, Ctx, S, Set),
        member(O, Set)
    ).

%   start_nodes(+How, +P, +Ctx, -Nodes): the nodes a path with both
%   ends unbound starts from: those P links for p+, every node of the
%   active graph when the path has a zero-length match.

start_nodes(How, P, Ctx, Nodes) :-
    (   How == one_or_more
    ->  Goal = path_holds(P, Ctx, X, Y)
    ;   Goal = triple(Ctx, X, _, Y)
    ),
    findall(N, ( call(Goal),
                 ( N = X ; N = Y )
               ), Nodes0),
    sort(Nodes0, Nodes).

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

